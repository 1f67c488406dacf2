// SPDX-License-Identifier: Apache-2.0
#include "bus/service/heartbeat_monitor.hpp"

#include <algorithm>
#include <stdexcept>

#include "bus/service/heartbeat_publisher.hpp"
#include "bus/transport/clock.hpp"

namespace wrc::bus {

HeartbeatMonitor::HeartbeatMonitor(lcm::LCM& lcm, std::string channel, double missed_periods)
    : channel_(std::move(channel)), missed_periods_(missed_periods), rejections_("heartbeat monitor on " + channel_) {
  if (!(missed_periods > 0.0)) {
    throw std::invalid_argument("missed periods " + std::to_string(missed_periods) + " is not positive");
  }
  subscription_ = std::make_unique<GuardedSubscription<wrc::heartbeat_t>>(
      lcm, channel_, "heartbeat monitor on " + channel_,
      [this](const wrc::heartbeat_t& hb, const ReceivedMessage& info) { on_heartbeat(hb, info); });
  subscription_->set_drop_observer([this](DropKind) { ++rejected_; });
}

void HeartbeatMonitor::on_heartbeat(const wrc::heartbeat_t& hb, const ReceivedMessage& info) {
  if (!(hb.period >= kMinHeartbeatPeriod && hb.period <= kMaxHeartbeatPeriod)) {
    ++rejected_;
    rejections_.reject(*info.channel, "heartbeat of " + hb.model.substr(0, 40) + "/" + hb.instance.substr(0, 40) +
                                          " has period " + std::to_string(hb.period) + " s outside [" + std::to_string(kMinHeartbeatPeriod) + ", " +
                                          std::to_string(kMaxHeartbeatPeriod) + "] (implausible)");
    return;
  }
  const double now = monotonic_seconds();
  if (now - last_sweep_ >= 1.0) forget_silent(now);
  Key key{hb.model, hb.instance, info.origin.nonce};
  auto it = table_.find(key);
  if (it == table_.end()) {
    if (table_.size() >= kMaxEntries) {
      forget_silent(now);
      if (table_.size() >= kMaxEntries) {
        table_.erase(std::min_element(table_.begin(), table_.end(), [](const auto& a, const auto& b) {
          return a.second.last_seen < b.second.last_seen;
        }));
      }
    }
    it = table_.emplace(std::move(key), ServiceStatus{}).first;
    it->second.first_seen = now;
    it->second.nonce = info.origin.nonce;
  }
  ServiceStatus& entry = it->second;
  entry.last = hb;
  entry.last_seen = now;
  ++entry.heartbeats;
  if (observer_) observer_(entry);
}

void HeartbeatMonitor::forget_silent(double now) {
  last_sweep_ = now;
  for (auto it = table_.begin(); it != table_.end();) {
    const double keep = std::max(kForgetMinimum, kForgetPeriods * it->second.last.period);
    it = now - it->second.last_seen > keep ? table_.erase(it) : std::next(it);
  }
}

bool HeartbeatMonitor::alive(const ServiceStatus& status, double now) const {
  return now - status.last_seen <= missed_periods_ * status.last.period;
}

ServiceStatus HeartbeatMonitor::evaluate(ServiceStatus status, double now) const {
  status.alive = alive(status, now);
  return status;
}

std::vector<ServiceStatus> HeartbeatMonitor::services(double now) const {
  std::vector<ServiceStatus> out;
  out.reserve(table_.size());
  for (const auto& entry : table_) out.push_back(evaluate(entry.second, now));
  std::stable_sort(out.begin(), out.end(), [](const ServiceStatus& a, const ServiceStatus& b) {
    return std::tie(a.last.model, a.last.instance, a.first_seen) < std::tie(b.last.model, b.last.instance, b.first_seen);
  });
  return out;
}

std::vector<ServiceStatus> HeartbeatMonitor::processes(const std::string& model, const std::string& instance,
                                                       double now) const {
  std::vector<ServiceStatus> out;
  for (auto it = table_.lower_bound(Key{model, instance, 0});
       it != table_.end() && std::get<0>(it->first) == model && std::get<1>(it->first) == instance; ++it)
    out.push_back(evaluate(it->second, now));
  return out;
}

std::optional<ServiceStatus> HeartbeatMonitor::find(const std::string& model, const std::string& instance,
                                                    double now) const {
  std::optional<ServiceStatus> best;
  for (ServiceStatus& s : processes(model, instance, now)) {
    if (!best || std::make_pair(s.available(), s.last_seen) > std::make_pair(best->available(), best->last_seen)) {
      best = std::move(s);
    }
  }
  return best;
}

std::vector<std::string> HeartbeatMonitor::ready_instances(const std::string& model, const std::string& geometry_key,
                                                           double now, const std::string& model_hash) const {
  std::vector<std::string> names;
  for (auto it = table_.lower_bound(Key{model, std::string(), 0}); it != table_.end() && std::get<0>(it->first) == model;
       ++it) {
    const ServiceStatus& s = it->second;
    if (ServiceStatus::says_available(s.last) && alive(s, now) &&
        (geometry_key.empty() || s.last.geometry_key == geometry_key) &&
        (model_hash.empty() || s.last.model_hash == model_hash))
      names.push_back(s.last.instance);
  }
  names.erase(std::unique(names.begin(), names.end()), names.end());  // the table is sorted by instance
  return names;
}

bool HeartbeatMonitor::available_before(const std::string& model, const std::string& instance, double now) const {
  for (auto it = table_.lower_bound(Key{model, std::string(), 0});
       it != table_.end() && std::get<0>(it->first) == model && std::get<1>(it->first) < instance; ++it) {
    const ServiceStatus& s = it->second;
    if (ServiceStatus::says_available(s.last) && alive(s, now)) return true;
  }
  return false;
}

}  // namespace wrc::bus
