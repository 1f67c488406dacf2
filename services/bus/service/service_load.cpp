// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <numeric>

#include "bus/service/percentile.hpp"
#include "bus/service/service_load.hpp"

namespace wrc::bus {

LatencyWindow::LatencyWindow(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {
  samples_.reserve(capacity_);
}

void LatencyWindow::add(double seconds) {
  if (samples_.size() < capacity_) {
    samples_.push_back(seconds);
  } else {
    samples_[next_] = seconds;
  }
  next_ = (next_ + 1) % capacity_;
}

void LatencyWindow::summarise(ServiceLoad& load) const {
  if (samples_.empty()) return;
  const double mean = std::accumulate(samples_.begin(), samples_.end(), 0.0) / samples_.size();
  load.latency_mean = std::max(load.latency_mean, mean);
  load.latency_p95 = std::max(load.latency_p95, percentile(samples_, 0.95));  // the one p95 rule
  load.latency_max = std::max(load.latency_max, *std::max_element(samples_.begin(), samples_.end()));
}

}  // namespace wrc::bus
