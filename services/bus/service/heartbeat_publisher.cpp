// SPDX-License-Identifier: Apache-2.0
#include "bus/service/heartbeat_publisher.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/drop_counters.hpp"

namespace wrc::bus {

HeartbeatPublisher::HeartbeatPublisher(lcm::LCM& lcm, std::string channel, ServiceIdentity identity,
                                       double period)
    : lcm_(lcm),
      channel_(std::move(channel)),
      identity_(std::move(identity)),
      period_(period),
      started_(monotonic_seconds()),
      started_utime_(wall_utime()),
      stamper_(sender_name(identity_.program, identity_.instance)),
      last_sent_(-1e300),
      last_fresh_(-1e300) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("heartbeat period " + std::to_string(period) + " s is not positive");
  }
}

void HeartbeatPublisher::set_state(std::int8_t state, std::string reason) {
  state_ = state;
  state_reason_ = std::move(reason);
  publish_now();
}

HeartbeatPublisher::~HeartbeatPublisher() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_keeper_ = true;
  }
  keeper_wakeup_.notify_all();
  if (keeper_.joinable()) keeper_.join();
}

bool HeartbeatPublisher::tick() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_tick_ = monotonic_seconds();
  }
  if (seconds_until_due() > 0.0) return false;
  publish_now();
  return true;
}

double HeartbeatPublisher::seconds_until_due() const {
  // Measured from the last heartbeat this process made, not from the keeper's copy of it: a copy
  // sent while the loop was a little late must not postpone the loop's own (the keeper's next
  // wake-up would fall on the next due time again, and every later heartbeat would be a copy).
  std::lock_guard<std::mutex> lock(mutex_);
  return std::max(0.0, last_fresh_ + period_ - monotonic_seconds());
}

std::int64_t HeartbeatPublisher::published() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return published_;
}

std::int64_t HeartbeatPublisher::kept_alive() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return kept_alive_;
}

void HeartbeatPublisher::start_keeper(double max_busy) {
  if (!(max_busy > 0.0)) throw std::invalid_argument("keeper: max_busy " + std::to_string(max_busy) + " s is not positive");
  std::lock_guard<std::mutex> lock(mutex_);
  if (keeper_.joinable()) return;
  max_busy_ = max_busy;
  last_tick_ = monotonic_seconds();
  keeper_ = std::thread([this] { keep_alive(); });
}

void HeartbeatPublisher::keep_alive() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_keeper_) {
    keeper_wakeup_.wait_for(lock, std::chrono::duration<double>(0.25 * period_));
    if (stop_keeper_) break;
    const double now = monotonic_seconds();
    if (published_ == 0 || now - last_sent_ < period_ || now - last_tick_ > max_busy_) continue;
    // The owner's loop is late but alive: the last heartbeat again, stamped anew.
    wrc::heartbeat_t hb = last_heartbeat_;
    stamper_.stamp(hb.header);
    hb.uptime = now - started_;
    send_locked(hb, now);
    ++kept_alive_;
  }
}

void HeartbeatPublisher::send_locked(const wrc::heartbeat_t& hb, double now) {
  if (publish_signed(lcm_, channel_, hb) != 0) {
    std::cerr << stamper_.sender() << ": publishing the heartbeat on " << channel_ << " failed\n";
  }
  last_sent_ = now;
  ++published_;
}

void HeartbeatPublisher::publish_now() {
  wrc::heartbeat_t hb{};
  hb.model = identity_.model;
  hb.instance = identity_.instance;
  hb.pid = static_cast<std::int32_t>(::getpid());
  hb.state = state_;
  hb.request_channel = identity_.request_channel;
  hb.interface_version = wrc::heartbeat_t::INTERFACE_VERSION;
  hb.period = period_;
  const double now = monotonic_seconds();
  hb.uptime = now - started_;
  hb.requests_handled = load_.requests_handled;
  hb.requests_rejected = load_.requests_rejected;
  hb.max_queue = load_.max_queue;
  hb.busy_fraction = load_.busy_fraction;
  hb.latency_mean = load_.latency_mean;
  hb.latency_p95 = load_.latency_p95;
  hb.latency_max = load_.latency_max;
  hb.geometry_key = geometry_key_;
  hb.model_hash = model_hash_;
  hb.started_utime = started_utime_;
  hb.state_reason = state_reason_;
  if (activity_source_) {
    try {
      hb.activity = activity_source_();
    } catch (const std::exception& e) {
      hb.activity = std::string("(activity unknown: ") + e.what() + ")";
    }
  }
  const DropCounts drops = drop_counts();
  hb.dropped_unsigned = drops.unsigned_messages();
  hb.dropped_bad_signature = drops.bad_signature();
  hb.dropped_replayed = drops.replayed();
  hb.dropped_malformed = drops.malformed();
  std::lock_guard<std::mutex> lock(mutex_);
  stamper_.stamp(hb.header);
  last_heartbeat_ = hb;
  last_fresh_ = now;
  send_locked(hb, now);
}

}  // namespace wrc::bus
