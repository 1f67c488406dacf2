// SPDX-License-Identifier: Apache-2.0
#include "bus/service/serving_activity.hpp"

#include <cmath>
#include <utility>

#include "bus/transport/clock.hpp"

namespace wrc::bus {

ServingActivity::ServingActivity(std::string what, std::function<std::int64_t()> answered)
    : what_(std::move(what)), answered_(std::move(answered)), last_time_(monotonic_seconds()) {
  last_answered_ = answered_();
}

std::string ServingActivity::operator()() {
  const double now = monotonic_seconds();
  const std::int64_t answered = answered_();
  const double rate = now > last_time_ ? static_cast<double>(answered - last_answered_) / (now - last_time_) : 0.0;
  last_answered_ = answered;
  last_time_ = now;
  return "serving " + what_ + ", " + std::to_string(std::lround(rate)) + " per second";
}

}  // namespace wrc::bus
