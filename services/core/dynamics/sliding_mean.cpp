// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/sliding_mean.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

void check_positive(const char* what, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    std::ostringstream msg;
    msg << "sliding mean: " << what << " " << v << " [m] is not a finite number > 0";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

DistanceSlidingMean::DistanceSlidingMean(double window, double interval) : window_(window), interval_(interval) {
  check_positive("window", window);
  check_positive("interval", interval);
}

void DistanceSlidingMean::clear() {
  samples_.clear();
  started_ = false;
}

DistanceSlidingMean::Sample DistanceSlidingMean::at(double s) const {
  // The last sample at or before s and the first after it (samples_ spans s).
  for (size_t k = samples_.size() - 1; k > 0; --k) {
    const Sample& a = samples_[k - 1];
    const Sample& b = samples_[k];
    if (a.s <= s && s <= b.s) {
      if (b.s == a.s) return b;
      const double w = (s - a.s) / (b.s - a.s);
      return {s, a.t + w * (b.t - a.t), a.v + w * (b.v - a.v)};
    }
  }
  return samples_.front();
}

double DistanceSlidingMean::integral(double a, double b) const {
  double sum = 0.0;
  for (size_t k = 1; k < samples_.size(); ++k) {
    const Sample& p = samples_[k - 1];
    const Sample& q = samples_[k];
    const double lo = std::max(a, p.s);
    const double hi = std::min(b, q.s);
    if (!(hi > lo)) continue;
    // The trapezoid of the linear piece between p and q, cut to [lo, hi].
    const double slope = (q.v - p.v) / (q.s - p.s);
    sum += (hi - lo) * (p.v + slope * (0.5 * (lo + hi) - p.s));
  }
  return sum;
}

void DistanceSlidingMean::add(double s, double t, double v, const OnMean& on_mean) {
  if (!std::isfinite(s) || !std::isfinite(v) || !std::isfinite(t)) return;
  if (!started_) {
    started_ = true;
    first_s_ = s;
    samples_.push_back({s, t, v});
    return;
  }
  const double last = samples_.back().s;
  if (s < last) {
    std::ostringstream msg;
    msg << "sliding mean: distance " << s << " m comes after " << last << " m";
    throw std::invalid_argument(msg.str());
  }
  samples_.push_back({s, t, v});
  // Window ends on the grid k * interval in (last, s], whose window starts at or after the first sample.
  for (double k = std::floor(last / interval_) + 1.0; k * interval_ <= s; k += 1.0) {
    const double end = k * interval_;
    const double start = end - window_;
    if (start < first_s_) continue;
    if (on_mean) on_mean({end, at(end).t, integral(start, end) / window_});
  }
  // Keep what the next windows need: from the last sample at or before (the next end - window).
  const double next_start = (std::floor(s / interval_) + 1.0) * interval_ - window_;
  while (samples_.size() > 2 && samples_[1].s <= next_start) samples_.pop_front();
}

}  // namespace wrc
