#include <algorithm>
#include <numeric>

#include "bus/service_load.hpp"

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
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  const double mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / sorted.size();
  const std::size_t i95 = std::min(sorted.size() - 1, (sorted.size() * 95 + 99) / 100 - 1);
  load.latency_mean = std::max(load.latency_mean, mean);
  load.latency_p95 = std::max(load.latency_p95, sorted[i95]);
  load.latency_max = std::max(load.latency_max, sorted.back());
}

}  // namespace wrc::bus
