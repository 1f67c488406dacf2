// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Detects a second live process with this process's model and instance name. Of two such
/// processes the one that started later (heartbeat_t::started_utime; ties: the larger pid, then
/// the larger sender nonce) is the duplicate: it refuses to serve, says so in its heartbeat
/// (state DUPLICATE, state_reason) and its log, and serves once the older one is gone. Both
/// decide from the same two heartbeats, so they agree. The service loop (bus/service/service_loop.hpp)
/// runs it for every service.

#include <lcm/lcm-cpp.hpp>

#include <optional>
#include <string>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/service/heartbeat_publisher.hpp"

namespace wrc::bus {

class DuplicateInstanceGuard {
 public:
  /// heartbeat_channel: full bus name of HEARTBEAT; self: this process's heartbeat (model,
  /// instance, start time), which must outlive the guard.
  DuplicateInstanceGuard(lcm::LCM& lcm, const std::string& heartbeat_channel, const HeartbeatPublisher& self);

  /// The older live process holding this name, if any (DRAINING ones do not count), at
  /// monotonic time now [s].
  std::optional<ServiceStatus> older_holder(double now) const;
  /// One line on why this process refuses to serve, naming holder's program, pid and start.
  std::string refusal(const ServiceStatus& holder) const;

 private:
  HeartbeatMonitor monitor_;
  const HeartbeatPublisher& self_;
};

}  // namespace wrc::bus
