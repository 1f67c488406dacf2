// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// ContactEvaluator over the bus: a batch of configurations as one contact_query_t to
/// wrc-contactd --model M, the reply turned back into library results. A query that gets no
/// reply is re-sent (same request id) and, when a whole round of attempts fails (the service died
/// and the launcher restarts it), asked again until the wait limit: a deterministic service gives
/// the same answer, so a run with a restarted service ends as an undisturbed one.
///
/// Spreading: unless the run names an instance, the queries go in turn to every READY instance of
/// the model with the run's geometry key and the model hash of the first answer (so a spline
/// model of another fit is never mixed in), each addressed by name, so that runs on several hosts'
/// instances share them (a sweep's runs as well as one run's queries). The list is read from the
/// heartbeats at most every kSpreadRefresh; with none READY a query goes unaddressed (the service
/// side's leader rule picks who answers).
///
/// Fail-over: a query that gets no reply in a whole round is sent at once to every READY instance
/// of the model with the run's geometry key, each addressed by name, and the first answer is
/// taken; an instance that failed a round is left out of the spreading for kSilencePause, and
/// the one that answered the fail-over is asked when none else is left. So an instance that
/// claims to be READY and never answers (hung, or a key holder's forged heartbeat) costs one round
/// every kSilencePause, not the run. Every instance with the same geometry key and model hash
/// computes the same answer, so the run is the same wherever its queries went.

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/request_client.hpp"
#include "core/dynamics/contact_evaluator.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::dynamics {

/// Where and how to ask.
struct BusContactSettings {
  std::string model;         ///< onepoint, interp, multipoint, spline
  std::string instance;      ///< empty: any instance
  std::string geometry_key;  ///< the key the service must compute with
  bus::CallPolicy policy;    ///< per-attempt timeout and re-sends
  double wait = 10.0;        ///< [s] longest wait for a service that answers, per query
  /// Called after every round of attempts without a reply (the service's heartbeat goes on
  /// while it waits for a restarted contact service).
  std::function<void()> keepalive;
};

class BusContact final : public ContactEvaluator {
 public:
  /// client: the dynamics' request client (its request channel is switched to the model's).
  /// monitor: heartbeats, to wait for a (restarted) service of the model.
  BusContact(bus::RequestClient<contact_query_t, contact_reply_t>& client, const bus::HeartbeatMonitor& monitor,
             const bus::ChannelNames& names, BusContactSettings settings);
  std::string model() const override { return settings_.model; }
  /// @throws OutsideModelError (OUTSIDE_MODEL), ContactConfigurationError (IMPOSSIBLE_CONFIGURATION,
  ///         NO_CONTACT), std::runtime_error (BAD_REQUEST, INTERNAL_ERROR, another geometry, no
  ///         reply within the wait limit), each naming the model and the service's message.
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override;
  long retries() const override { return retries_; }
  long timeouts() const override { return timeouts_; }
  long failovers() const override { return failovers_; }
  QueryTimes query_times() const override { return times_; }
  /// The instance that answered the last fail-over (asked when no other is left to spread over).
  const std::string& addressed_instance() const { return addressed_; }
  /// [-] queries answered, per answering instance's name.
  const std::map<std::string, long>& instance_queries() const { return answered_by_; }

  /// [s] how often the list of instances to spread over is read from the heartbeats.
  static constexpr double kSpreadRefresh = 0.25;
  /// [s] how long an instance that failed a round is left out of the spreading.
  static constexpr double kSilencePause = 5.0;

 private:
  /// Adds where an answered call's time went to times_.
  void add_times(const bus::CallResult<contact_reply_t>& result);
  /// One message for queries that share formulation, material, grid and speed.
  std::vector<ContactResult> evaluate_message(const std::vector<ContactQuery>& batch);
  /// The instance the next query goes to (empty: unaddressed).
  std::string spread_target();
  /// The result of an answered call, checked (geometry key, status, size), the instance counted.
  std::vector<ContactResult> take_reply(const contact_reply_t& reply, std::size_t expected);

  bus::RequestClient<contact_query_t, contact_reply_t>& client_;
  const bus::HeartbeatMonitor& monitor_;
  std::string request_channel_;
  BusContactSettings settings_;
  long retries_ = 0;
  long timeouts_ = 0;
  long failovers_ = 0;
  QueryTimes times_;
  std::string addressed_;  ///< instance that answered the last fail-over
  std::string model_hash_;  ///< of the first answer: only instances with this hash are spread over
  std::vector<std::string> spread_over_;  ///< READY instances with the run's key and model hash
  std::size_t spread_last_ = static_cast<std::size_t>(-1);  ///< index into spread_over_ of the last query's instance
  double spread_refresh_ = 0.0;           ///< [s] monotonic time spread_over_ is read again
  std::map<std::string, double> paused_until_;  ///< [s] instances left out after a silent round
  std::map<std::string, long> answered_by_;     ///< [-] answered queries per instance
};


/// Whether a service of model (and instance) with geometry_key is alive and READY now; the
/// reason when not ("no READY onepoint service with geometry key ab12.. on the bus").
std::string missing_service_reason(const bus::HeartbeatMonitor& monitor, const std::string& model,
                                   const std::string& instance, const std::string& geometry_key);

}  // namespace wrc::dynamics
