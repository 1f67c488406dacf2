// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/limit_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wrc {
namespace {

struct Extremum {
  double t = 0;
  double x = 0;
  bool peak = false;
};

// The vertex of the parabola through (t0, x0), (t1, x1), (t2, x2), t1 the middle sample.
Extremum vertex(double t0, double x0, double t1, double x1, double t2, double x2, bool peak) {
  const double d0 = (x1 - x0) / (t1 - t0), d1 = (x2 - x1) / (t2 - t1);
  const double curvature = (d1 - d0) / (t2 - t0);  // half the second derivative
  if (curvature == 0.0) return {t1, x1, peak};
  // Newton form: p(t) = x0 + d0 (t - t0) + curvature (t - t0)(t - t1); p'(t) = d0 + curvature (2t - t0 - t1).
  const double tv = 0.5 * (t0 + t1) - d0 / (2.0 * curvature);
  if (!(tv > t0 && tv < t2)) return {t1, x1, peak};
  const double xv = x0 + d0 * (tv - t0) + curvature * (tv - t0) * (tv - t1);
  return {tv, xv, peak};
}

}  // namespace

CycleMeasurement measure_cycle(const std::vector<double>& t, const std::vector<double>& x, double from, int periods,
                               double to) {
  if (t.size() != x.size())
    throw std::invalid_argument("measure_cycle: " + std::to_string(t.size()) + " times but " +
                                std::to_string(x.size()) + " values");
  if (periods < 1) throw std::invalid_argument("measure_cycle: periods = " + std::to_string(periods) + ", must be >= 1");
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw std::invalid_argument("measure_cycle: times not increasing at sample " + std::to_string(i) + " (" +
                                  std::to_string(t[i - 1]) + " then " + std::to_string(t[i]) + " s)");
  CycleMeasurement m;
  std::vector<Extremum> extremes;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < from || t[i] >= to) continue;
    m.largest = std::max(m.largest, std::abs(x[i]));
    if (i == 0 || i + 1 >= t.size() || t[i - 1] < from || t[i + 1] >= to) continue;
    const bool peak = x[i] > x[i - 1] && x[i] >= x[i + 1];
    const bool trough = x[i] < x[i - 1] && x[i] <= x[i + 1];
    if (peak || trough) extremes.push_back(vertex(t[i - 1], x[i - 1], t[i], x[i], t[i + 1], x[i + 1], peak));
  }
  // Cycles: a peak and the first trough after it. An extremum counts only when it differs from the
  // last counted one of the other kind by more than kHysteresis of the window's range (a wiggle of
  // the integrator's or the contact's noise on a flank is no cycle); of two of a kind in a row the
  // more extreme one is kept.
  constexpr double kHysteresis = 0.01;
  const double threshold = kHysteresis * 2.0 * half_range(t, x, from, to);
  std::vector<Extremum> alternating;
  for (const Extremum& e : extremes) {
    if (!alternating.empty() && alternating.back().peak == e.peak) {
      Extremum& last = alternating.back();
      if (e.peak ? e.x > last.x : e.x < last.x) last = e;
      continue;
    }
    if (!alternating.empty() && std::abs(e.x - alternating.back().x) <= threshold) continue;
    alternating.push_back(e);
  }
  std::vector<double> amplitudes, means, peak_times;
  for (std::size_t i = 0; i < alternating.size(); ++i) {
    if (!alternating[i].peak) continue;
    peak_times.push_back(alternating[i].t);
    if (i + 1 < alternating.size()) {
      amplitudes.push_back(0.5 * (alternating[i].x - alternating[i + 1].x));
      means.push_back(0.5 * (alternating[i].x + alternating[i + 1].x));
    }
  }
  m.cycles = static_cast<int>(amplitudes.size());
  if (!amplitudes.empty()) {
    m.amplitude = amplitudes.back();
    m.mean = means.back();
    m.largest_amplitude = *std::max_element(amplitudes.begin(), amplitudes.end());
  }
  // The mean ratio of successive cycles over the last up to `periods` + 1 cycles.
  if (amplitudes.size() >= 2) {
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(periods), amplitudes.size() - 1);
    const double first = amplitudes[amplitudes.size() - 1 - n];
    if (first > 0) m.growth = std::pow(amplitudes.back() / first, 1.0 / static_cast<double>(n));
  }
  if (peak_times.size() >= 2) {
    const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(periods), peak_times.size() - 1);
    m.period = (peak_times.back() - peak_times[peak_times.size() - 1 - n]) / static_cast<double>(n);
  }
  return m;
}

double half_range(const std::vector<double>& t, const std::vector<double>& x, double from, double to) {
  if (t.size() != x.size())
    throw std::invalid_argument("half_range: " + std::to_string(t.size()) + " times but " +
                                std::to_string(x.size()) + " values");
  double lo = 0, hi = 0;
  bool any = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < from || t[i] >= to) continue;
    lo = any ? std::min(lo, x[i]) : x[i];
    hi = any ? std::max(hi, x[i]) : x[i];
    any = true;
  }
  return 0.5 * (hi - lo);
}

}  // namespace wrc
