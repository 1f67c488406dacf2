// SPDX-License-Identifier: Apache-2.0
#include "bus/service/duplicate_instance_guard.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <tuple>

#include "bus/auth/bus_auth.hpp"
#include "bus/service/log_text.hpp"

namespace wrc::bus {

namespace {
// Nonces followed at most (the monitor's table holds as many processes).
constexpr std::size_t kMaxFollowedNonces = HeartbeatMonitor::kMaxEntries;
}  // namespace

DuplicateInstanceGuard::DuplicateInstanceGuard(lcm::LCM& lcm, const std::string& heartbeat_channel,
                                               const HeartbeatPublisher& self)
    : monitor_(lcm, heartbeat_channel), self_(self) {
  monitor_.set_observer([claims = claims_, impostors = impostors_, &self](const ServiceStatus& s) {
    if (s.last.model != self.identity().model || s.last.instance != self.identity().instance) return;
    if (s.nonce == bus_auth().nonce() || impostors->count(s.nonce)) return;
    const std::pair<std::int32_t, std::int64_t> claim{s.last.pid, s.last.started_utime};
    auto [it, fresh] = claims->first.emplace(s.nonce, claim);
    const bool names_this_process = s.last.pid == static_cast<std::int32_t>(::getpid());
    if ((!fresh && it->second != claim) || names_this_process) {
      if (impostors->size() < kMaxFollowedNonces) impostors->insert(s.nonce);
      std::cerr << self.identity().program << "/" << self.identity().instance << ": ignoring heartbeats of "
                << log_text(s.last.header.sender) << " (pid " << s.last.pid << "): "
                << (names_this_process ? "they name this process's pid under another sender identity"
                                       : "they claim another pid or start than its first heartbeat")
                << "\n";
    }
    if (claims->first.size() > kMaxFollowedNonces) claims->first.erase(claims->first.begin());
  });
}

std::optional<ServiceStatus> DuplicateInstanceGuard::older_holder(double now) const {
  const std::uint64_t own_nonce = bus_auth().nonce();
  const auto own = std::make_tuple(self_.started_utime(), static_cast<std::int64_t>(::getpid()), own_nonce);
  std::optional<ServiceStatus> oldest;
  // Only the entries of this name: the table may hold 512 processes (a flood of heartbeats), and
  // this runs four times a period.
  for (const ServiceStatus& s : monitor_.processes(self_.identity().model, self_.identity().instance, now)) {
    if (!s.alive || s.nonce == own_nonce || s.last.state == wrc::heartbeat_t::DRAINING) continue;
    if (impostors_->count(s.nonce)) continue;  // claims that are not its own
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
