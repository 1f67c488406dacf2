// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// ContactEvaluator over the bus: a batch of configurations as one contact_query_t to
/// wrc-contactd --model M, the reply turned back into library results. A query that gets no
/// reply is re-sent (same request id) and, when a whole round of attempts fails (the service died
/// and the launcher restarts it), asked again until the wait limit: a deterministic service gives
/// the same answer, so a run with a restarted service ends as an undisturbed one.
///
/// Spreading: unless the run names an instance, the queries go in turn to every instance of the
/// model that has answered this client (each addressed by name), so that the instances on several
/// hosts share a run's and a sweep's load. An instance that beats READY with the run's geometry
/// key and the model hash of the first answer (a spline model of another fit is never mixed in)
/// but has not answered yet is probed: at most one query every kProbeInterval goes to it with a
/// short timeout (kProbeTimeout, no re-send); an answer adds it to the turn, silence leaves it out
/// for kProbePause and the query goes to the turn at once. So a flood of forged READY heartbeats
/// (a key holder's) costs at most kProbeTimeout every kProbeInterval, never a round. With nobody
/// in the turn yet a query goes to every READY instance at once, the first answer taken (with none
/// READY, to the instance that answered the last fail-over, else unaddressed: the service side's
/// leader rule picks who answers). An answer computed with another model hash is refused and its
/// instance left out, as a silent one.
///
/// Fail-over: a query that gets no reply in a whole round is sent at once to every READY instance
/// of the model with the run's geometry key, each addressed by name, and the first answer is
/// taken; the silent instance leaves the turn for kProbePause. So an instance that stops answering
/// (hung, its host cut off) costs one round, not the run. Every instance with the same geometry
/// key and model hash computes the same answer, so the run is the same wherever its queries went.

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
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
  /// Any number of configurations: a batch goes as one message per run of at most
  /// protocol::kMaxConfigurations configurations that share the fields a message carries once.
  /// Where none of them follows a configuration of another message, all go at once, each to the
  /// next instance in the turn (one round trip; a message without an answer then goes again on
  /// its own, with the fail-over); otherwise one after the other, a configuration that follows
  /// one of an earlier message taking that answer's points before it is sent.
  /// @throws OutsideModelError (OUTSIDE_MODEL), ContactConfigurationError (IMPOSSIBLE_CONFIGURATION,
  ///         NO_CONTACT), std::runtime_error (BAD_REQUEST, INTERNAL_ERROR, another geometry, no
  ///         reply within the wait limit), each naming the model and the service's message.
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override;
  long retries() const override { return retries_; }
  long timeouts() const override { return timeouts_; }
  long failovers() const override { return failovers_; }
  QueryTimes query_times() const override { return times_; }
  /// The instance that answered the last fail-over.
  const std::string& addressed_instance() const { return addressed_; }
  /// [-] queries answered, per answering instance's name.
  const std::map<std::string, long>& instance_queries() const { return answered_by_; }
  /// [-] probes of READY instances that did not answer.
  long failed_probes() const { return failed_probes_; }
  /// [-] answers computed with another model hash than the run's, refused.
  long other_model_answers() const { return other_model_answers_; }

  /// [s] how often the READY instances are read from the heartbeats.
  static constexpr double kSpreadRefresh = 0.25;
  /// [s] at most one probe of an instance that has not answered yet per this time.
  static constexpr double kProbeInterval = 0.25;
  /// [s] how long a probe waits for its answer (a contact round trip takes 0.05-0.2 ms on one host).
  static constexpr double kProbeTimeout = 0.02;
  /// [s] how long an instance that failed a probe or a round is left out.
  static constexpr double kProbePause = 10.0;

 private:
  /// Adds where an answered call's time went to times_.
  void add_times(const bus::CallResult<contact_reply_t>& result);
  /// One message for queries that share formulation, material, grid and speed.
  std::vector<ContactResult> evaluate_message(const std::vector<ContactQuery>& batch);
  /// The queries of batch[begin, end) as one message: follows renumbered within it, or, for one
  /// of an earlier message, that configuration's answer in answered followed.
  static std::vector<ContactQuery> message_queries(const std::vector<ContactQuery>& batch, std::size_t begin,
                                                   std::size_t end, const std::vector<ContactResult>& answered);
  /// Every message of batch at once (call_each), each to the next instance in the turn.
  std::vector<ContactResult> evaluate_at_once(const std::vector<ContactQuery>& batch,
                                              const std::vector<std::pair<std::size_t, std::size_t>>& messages);
  /// Where the next query goes.
  struct Target {
    std::string instance;  ///< empty: unaddressed
    bool probe = false;    ///< an instance that has not answered yet
  };
  Target spread_target();
  /// Reads the READY instances again when kSpreadRefresh has passed: the turn keeps those still
  /// READY, the candidates are the others with the run's key and model hash, not paused.
  void refresh_instances(double now);
  /// Leaves instance out (of the turn and the candidates) for kProbePause.
  void pause(const std::string& instance);
  /// Whether an answer was computed with another model hash than the run's (then counted, and its
  /// instance left out).
  bool of_another_model(const bus::CallResult<contact_reply_t>& result);
  /// The query to each of instances by name at once, the first answer taken.
  bus::CallResult<contact_reply_t> ask_all(const contact_query_t& query, const std::vector<std::string>& instances);
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
  std::string model_hash_;  ///< of the first answer: only instances with this hash are asked
  std::vector<std::string> turn_;        ///< READY instances that have answered, by name
  std::vector<std::string> candidates_;  ///< READY instances with the key and hash that have not
  std::size_t turn_last_ = static_cast<std::size_t>(-1);  ///< index into turn_ of the last query's instance
  double refresh_at_ = 0.0;   ///< [s] monotonic time the instances are read again
  double next_probe_ = 0.0;   ///< [s] monotonic time before which no probe is sent
  std::map<std::string, double> paused_until_;  ///< [s] instances left out after a silent probe or round
  std::map<std::string, long> answered_by_;     ///< [-] answered queries per instance
  long failed_probes_ = 0;
  long other_model_answers_ = 0;
};


/// Whether a service of model (and instance) with geometry_key is alive and READY now; the
/// reason when not ("no READY onepoint service with geometry key ab12.. on the bus").
std::string missing_service_reason(const bus::HeartbeatMonitor& monitor, const std::string& model,
                                   const std::string& instance, const std::string& geometry_key);

}  // namespace wrc::dynamics
