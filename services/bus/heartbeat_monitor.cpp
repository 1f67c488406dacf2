#include "bus/heartbeat_monitor.hpp"

#include <stdexcept>

#include "bus/channels.hpp"
#include "bus/clock.hpp"
#include "bus/decode.hpp"

namespace wrc::bus {

HeartbeatMonitor::HeartbeatMonitor(lcm::LCM& lcm, std::string channel, double missed_periods)
    : lcm_(lcm),
      channel_(std::move(channel)),
      missed_periods_(missed_periods),
      rejections_("heartbeat monitor on " + channel_) {
  if (!(missed_periods > 0.0)) {
    throw std::invalid_argument("missed periods " + std::to_string(missed_periods) + " is not positive");
  }
  subscription_ = lcm_.subscribe(regex_escape(channel_), &HeartbeatMonitor::on_heartbeat, this);
  if (subscription_ == nullptr) throw std::runtime_error("cannot subscribe to '" + channel_ + "'");
  subscription_->setQueueCapacity(1000);
}

HeartbeatMonitor::~HeartbeatMonitor() { lcm_.unsubscribe(subscription_); }

void HeartbeatMonitor::on_heartbeat(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  wrc::heartbeat_t hb{};
  if (std::string why = decode_message(*rbuf, hb); !why.empty()) {
    rejections_.reject(channel, why);
    return;
  }
  if (!(hb.period > 0.0) || hb.period > 3600.0) {
    rejections_.reject(channel, "heartbeat of " + hb.model + "/" + hb.instance + " has period " +
                                    std::to_string(hb.period) + " s outside (0, 3600]");
    return;
  }
  const double now = monotonic_seconds();
  auto& entry = table_[{hb.model, hb.instance}];
  if (entry.heartbeats == 0 || entry.last.pid != hb.pid) entry.first_seen = now;
  entry.last = std::move(hb);
  entry.last_seen = now;
  ++entry.heartbeats;
}

ServiceStatus HeartbeatMonitor::evaluate(ServiceStatus status, double now) const {
  status.alive = now - status.last_seen <= missed_periods_ * status.last.period;
  return status;
}

std::vector<ServiceStatus> HeartbeatMonitor::services(double now) const {
  std::vector<ServiceStatus> out;
  out.reserve(table_.size());
  for (const auto& entry : table_) out.push_back(evaluate(entry.second, now));
  return out;
}

std::optional<ServiceStatus> HeartbeatMonitor::find(const std::string& model,
                                                    const std::string& instance, double now) const {
  auto it = table_.find({model, instance});
  if (it == table_.end()) return std::nullopt;
  return evaluate(it->second, now);
}

}  // namespace wrc::bus
