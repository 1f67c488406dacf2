// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The main loop every service runs: dispatch LCM messages with handleTimeout, send heartbeats
/// with the aggregated load, refuse to serve while an older process holds the same model and
/// instance name (bus/service/duplicate_instance_guard.hpp), and on SIGINT/SIGTERM publish a DRAINING
/// heartbeat and return.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bus/service/duplicate_instance_guard.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/service/service_load.hpp"
#include "bus/transport/inbox.hpp"

namespace wrc::bus {

/// [s] the longest a service's loop may take to come round (one handler, one piece of periodic
/// work) before its heartbeats stop: up to then the heartbeat keeper thread covers for it
/// (HeartbeatPublisher::start_keeper). The longest legitimate wait is the dynamics' wait for a
/// restarted contact service (contact_wait, 10 s by default); a loop stuck for 30 s is hung, and
/// the launcher kills it 20 periods after its heartbeats stop.
inline constexpr double kMaxBusyLoop = 30.0;

/// Loads the bus key (bus/auth/bus_auth.hpp: bus_key_path(bus_key_option), unless one is loaded) and
/// opens LCM at url (empty = default). Throws std::runtime_error naming the key file or the URL
/// when either is not usable (no key, bad permissions, no multicast route).
std::unique_ptr<lcm::LCM> open_lcm(const std::string& url, const std::string& bus_key_option = "");

/// Service main loop. Typical use:
/// ```
/// ShutdownSignal::install();
/// auto lcm = open_lcm(options.lcm_url);
/// HeartbeatPublisher heartbeat(*lcm, names.name(channel::kHeartbeat), identity, period);
/// RequestServer<Req, Rep> server(...);
/// ServiceLoop loop(*lcm, heartbeat);
/// loop.add_load_source(&server);
/// return loop.run();
/// ```
class ServiceLoop {
 public:
  /// Listens on the heartbeat's channel for duplicates of this process.
  ServiceLoop(lcm::LCM& lcm, HeartbeatPublisher& heartbeat)
      : heartbeat_(heartbeat), duplicates_(lcm, heartbeat.channel(), heartbeat), inboxes_{lcm} {}

  /// Dispatches the messages of another inbox too (a lane of the bus the service serves on, as an
  /// LCM object or a lane socket; bus/transport/lcm_url.hpp). It must outlive the loop.
  void add_inbox(Inbox other) { inboxes_.push_back(other); }

  /// Adds a request server whose load goes into the heartbeat.
  void add_load_source(LoadSource* source) { sources_.push_back(source); }
  /// Called once per loop iteration (at least every heartbeat period). An exception from it is
  /// logged (rate-limited) and the loop goes on.
  void set_idle_hook(std::function<void()> hook) { idle_hook_ = std::move(hook); }
  /// [s] longest wait in one handleTimeout call (default 0.1), bounds the reaction to a signal.
  void set_max_wait(double seconds) { max_wait_ = seconds; }

  /// Starts the heartbeat keeper (kMaxBusyLoop), listens for 1.1 heartbeat periods (an older holder of the name is heard in that time),
  /// publishes READY (or DUPLICATE), loops until ShutdownSignal::requested(), publishes
  /// DRAINING. Returns the process exit code: 0 after a clean shutdown, 1 when LCM failed.
  int run();

 private:
  void report_load(double period_elapsed);
  /// Goes DUPLICATE (sources stop serving) or back to READY as the older holder comes and goes.
  void check_identity(double now);
  /// Dispatches what arrives for up to `seconds`; false when LCM failed.
  bool listen(double seconds);
  /// The idle hook, its exceptions caught and logged.
  void run_idle_hook();

  HeartbeatPublisher& heartbeat_;
  DuplicateInstanceGuard duplicates_;
  bool duplicate_ = false;
  double next_identity_check_ = 0.0;  // [s] monotonic time of the next duplicate check
  std::vector<LoadSource*> sources_;
  std::function<void()> idle_hook_;
  std::int64_t idle_failures_ = 0;       // exceptions of the idle hook since the start
  double next_idle_failure_log_ = 0.0;  // [s] monotonic time before which no failure is logged
  double max_wait_ = 0.1;
  int max_queue_ = 0;  // most messages handled back to back without waiting, this period, minus 1
  std::vector<Inbox> inboxes_;  // the bus first, then lanes
};

}  // namespace wrc::bus
