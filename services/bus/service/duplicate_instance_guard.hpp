// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Detects a second live process with this process's model and instance name. Of two such
/// processes the one that started later (heartbeat_t::started_utime; ties: the larger pid, then
/// the larger sender nonce) is the duplicate: it refuses to serve, says so in its heartbeat
/// (state DUPLICATE, state_reason) and its log, and serves once the older one is gone. Both
/// decide from the same two heartbeats, so they agree. The service loop (bus/service/service_loop.hpp)
/// runs it for every service.
///
/// What counts as another process is its signing nonce (the sender identity of its messages'
/// authentication trailer), followed as the launcher follows its children: the pid and start
/// time a nonce first claims are its identity, and a nonce whose heartbeats later claim another
/// pid or start is no instance (its claims are not its own). A heartbeat under another nonce
/// that claims this process's own pid is a claim about this process, not another instance (two
/// processes with one pid and one name would need two hosts that chose the same pid): neither
/// makes a service stand down. A bus-key holder can still forge an older instance of another
/// pid; that one stands a service down until its heartbeats stop (docs/bus-security.md).

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

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

  /// Nonces ignored so far because their claims were not their own [-].
  std::size_t impostors() const { return impostors_->size(); }

 private:
  // The (pid, started_utime) each nonce of this name first claimed, and the nonces that later
  // claimed another or named this process's pid (shared with the monitor's observer).
  struct Claims {
    std::map<std::uint64_t, std::pair<std::int32_t, std::int64_t>> first;
  };
  std::shared_ptr<Claims> claims_ = std::make_shared<Claims>();
  std::shared_ptr<std::set<std::uint64_t>> impostors_ = std::make_shared<std::set<std::uint64_t>>();
  HeartbeatMonitor monitor_;
  const HeartbeatPublisher& self_;
};

}  // namespace wrc::bus
