// SPDX-License-Identifier: Apache-2.0
#include "bus/service/duplicate_instance_guard.hpp"

#include <unistd.h>

#include <cstdio>
#include <tuple>

#include "bus/auth/bus_auth.hpp"

namespace wrc::bus {

DuplicateInstanceGuard::DuplicateInstanceGuard(lcm::LCM& lcm, const std::string& heartbeat_channel,
                                               const HeartbeatPublisher& self)
    : monitor_(lcm, heartbeat_channel), self_(self) {}

std::optional<ServiceStatus> DuplicateInstanceGuard::older_holder(double now) const {
  const std::uint64_t own_nonce = bus_auth().nonce();
  const auto own = std::make_tuple(self_.started_utime(), static_cast<std::int64_t>(::getpid()), own_nonce);
  std::optional<ServiceStatus> oldest;
  // Only the entries of this name: the table may hold 512 processes (a flood of heartbeats), and
  // this runs four times a period.
  for (const ServiceStatus& s : monitor_.processes(self_.identity().model, self_.identity().instance, now)) {
    if (!s.alive || s.nonce == own_nonce || s.last.state == wrc::heartbeat_t::DRAINING) continue;
    const auto other = std::make_tuple(s.last.started_utime, static_cast<std::int64_t>(s.last.pid), s.nonce);
    if (other < own && (!oldest || s.last.started_utime < oldest->last.started_utime)) oldest = s;
  }
  return oldest;
}

std::string DuplicateInstanceGuard::refusal(const ServiceStatus& holder) const {
  char earlier[32];
  std::snprintf(earlier, sizeof earlier, "%.1f", 1e-6 * static_cast<double>(self_.started_utime() - holder.last.started_utime));
  return "instance '" + self_.identity().instance + "' of model " + self_.identity().model + " is already served by " +
         holder.last.header.sender + " (pid " + std::to_string(holder.last.pid) + ", started " + earlier +
         " s earlier); not serving while it is alive";
}

}  // namespace wrc::bus
