#pragma once
/// @file
/// The main loop every service runs: dispatch LCM messages with handleTimeout, send heartbeats
/// with the aggregated load, and on SIGINT/SIGTERM publish a DRAINING heartbeat and return.

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bus/heartbeat_publisher.hpp"
#include "bus/service_load.hpp"

namespace wrc::bus {

/// Opens LCM at url (empty = default). Throws std::runtime_error naming the URL when LCM is not
/// usable (e.g. no multicast route).
std::unique_ptr<lcm::LCM> open_lcm(const std::string& url);

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
  ServiceLoop(lcm::LCM& lcm, HeartbeatPublisher& heartbeat) : lcm_(lcm), heartbeat_(heartbeat) {}

  /// Adds a request server whose load goes into the heartbeat.
  void add_load_source(LoadSource* source) { sources_.push_back(source); }
  /// Called once per loop iteration (at least every heartbeat period).
  void set_idle_hook(std::function<void()> hook) { idle_hook_ = std::move(hook); }
  /// [s] longest wait in one handleTimeout call (default 0.1), bounds the reaction to a signal.
  void set_max_wait(double seconds) { max_wait_ = seconds; }

  /// Publishes READY, loops until ShutdownSignal::requested(), publishes DRAINING. Returns the
  /// process exit code: 0 after a clean shutdown, 1 when LCM failed.
  int run();

 private:
  void report_load(double period_elapsed);

  lcm::LCM& lcm_;
  HeartbeatPublisher& heartbeat_;
  std::vector<LoadSource*> sources_;
  std::function<void()> idle_hook_;
  double max_wait_ = 0.1;
  int max_queue_ = 0;  // most messages handled back to back without waiting, this period, minus 1
};

}  // namespace wrc::bus
