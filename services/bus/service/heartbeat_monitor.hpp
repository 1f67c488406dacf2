// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Listens to heartbeats and keeps the table of service processes on the bus: alive while
/// heartbeats arrive, dead after `missed_periods` (default 3) periods without one, forgotten
/// after kForgetPeriods periods (at least kForgetMinimum) without one. One entry per process
/// (model, instance, and the sender nonce of its authentication trailer), so that two processes
/// claiming one name both show; at most kMaxEntries entries, the longest silent one evicted
/// first when a new process appears. Heartbeats arrive through the guarded path.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/rejection_log.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus {

/// What the monitor knows about one service process.
struct ServiceStatus {
  wrc::heartbeat_t last;         ///< last heartbeat received
  std::uint64_t nonce = 0;       ///< [-] sender nonce of the process (random per start)
  double last_seen = 0.0;        ///< [s] monotonic time it arrived
  double first_seen = 0.0;       ///< [s] monotonic time of the first heartbeat
  std::int64_t heartbeats = 0;   ///< heartbeats received
  bool alive = false;            ///< heartbeats still arriving (not yet missed_periods late)
  /// Alive, READY and built with this interface version: may be sent requests.
  bool available() const { return alive && says_available(last); }
  /// The heartbeat says READY, of this interface version.
  static bool says_available(const wrc::heartbeat_t& hb) {
    return hb.state == wrc::heartbeat_t::READY && hb.interface_version == wrc::heartbeat_t::INTERFACE_VERSION;
  }
};

/// Heartbeat listener. Dispatch happens in the owner's LCM handle loop.
class HeartbeatMonitor {
 public:
  static constexpr double kForgetPeriods = 10.0;    ///< [-] periods of silence before an entry goes
  static constexpr double kForgetMinimum = 2.0;     ///< [s] an entry stays at least this long
  static constexpr std::size_t kMaxEntries = 512;   ///< [-] processes in the table at most

  /// channel: full bus name of the heartbeat channel. missed_periods > 0.
  HeartbeatMonitor(lcm::LCM& lcm, std::string channel, double missed_periods = 3.0);
  HeartbeatMonitor(const HeartbeatMonitor&) = delete;
  HeartbeatMonitor& operator=(const HeartbeatMonitor&) = delete;

  /// Every process in the table, alive flags evaluated at monotonic time now [s], sorted by
  /// model, instance, then first heard of.
  std::vector<ServiceStatus> services(double now) const;
  /// Every process heard of as model/instance (usually one; two while a duplicate or a restart
  /// overlaps), alive flags evaluated at monotonic time now [s]. Copies only those entries.
  std::vector<ServiceStatus> processes(const std::string& model, const std::string& instance, double now) const;
  /// The process of model/instance to use, if heard of: an available one before others, then
  /// the one heard from last.
  std::optional<ServiceStatus> find(const std::string& model, const std::string& instance, double now) const;
  /// The names of the available (alive, READY, this interface version) instances of model that
  /// compute with geometry_key and model_hash (any when empty) at monotonic time now [s]: sorted,
  /// each once.
  std::vector<std::string> ready_instances(const std::string& model, const std::string& geometry_key,
                                           double now, const std::string& model_hash = "") const;
  /// Whether an available instance of model with a name that sorts before instance is heard at
  /// monotonic time now [s]. Walks only those entries and copies nothing: a contact service asks
  /// it for every unaddressed query, with up to kMaxEntries entries in the table.
  bool available_before(const std::string& model, const std::string& instance, double now) const;
  /// Called with the entry of every heartbeat accepted, as it is entered (a supervisor follows its
  /// children this way without copying the table).
  void set_observer(std::function<void(const ServiceStatus&)> observer) { observer_ = std::move(observer); }
  /// Heartbeats dropped by the guarded path or out of range.
  std::int64_t rejected() const { return rejected_; }
  /// Entries in the table now.
  std::size_t size() const { return table_.size(); }

 private:
  using Key = std::tuple<std::string, std::string, std::uint64_t>;  // model, instance, nonce
  void on_heartbeat(const wrc::heartbeat_t& hb, const ReceivedMessage& info);
  ServiceStatus evaluate(ServiceStatus status, double now) const;
  bool alive(const ServiceStatus& status, double now) const;
  void forget_silent(double now);

  std::string channel_;
  double missed_periods_;
  RejectionLog rejections_;
  std::int64_t rejected_ = 0;
  double last_sweep_ = -1e300;  // [s] monotonic time forget_silent() last ran
  std::map<Key, ServiceStatus> table_;
  std::function<void(const ServiceStatus&)> observer_;
  std::unique_ptr<GuardedSubscription<wrc::heartbeat_t>> subscription_;
};

}  // namespace wrc::bus
