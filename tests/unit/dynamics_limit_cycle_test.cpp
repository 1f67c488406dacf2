// SPDX-License-Identifier: Apache-2.0
// The measurement of an oscillation's last cycles (core/dynamics/limit_cycle.hpp,
// docs/bifurcation.md) on synthetic signals whose amplitude, period, mean and growth are known.
//
// Sampling as a hunting run samples: every 1 ms, at 5 Hz (200 samples a period). A sampled peak
// is low by 1 - cos(omega h / 2) at most (1.2e-4 relative at 5 Hz); the parabola through three
// samples leaves an error of order (omega h)^4 / 8 ~ 1e-7 relative, so the amplitudes are asked to
// 1e-5 relative (a tenth of what the unrefined samples could miss, a hundred times the parabola's
// error). The period from peak times: the vertex is off by of order h (omega h)^2 / 24 ~ 4e-8 s
// per peak; 1e-6 s is asked.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/dynamics/limit_cycle.hpp"
#include "expect_invalid.hpp"

namespace wrc {
namespace {

struct Signal {
  std::vector<double> t, x;
};

// x = mean + A exp(sigma t) sin(2 pi f t + phase), sampled every h from 0 to t_end.
Signal oscillation(double amplitude, double frequency, double sigma, double mean, double t_end,
                   double h = 1e-3, double phase = 0.3) {
  Signal s;
  for (long i = 0; i * h <= t_end + 1e-12; ++i) {
    const double t = i * h;
    s.t.push_back(t);
    s.x.push_back(mean + amplitude * std::exp(sigma * t) * std::sin(2 * M_PI * frequency * t + phase));
  }
  return s;
}

TEST(LimitCycle, ConstantAmplitudePeriodAndMean) {
  const Signal s = oscillation(4e-3, 5.0, 0.0, 1e-4, 4.0);
  const CycleMeasurement m = measure_cycle(s.t, s.x, 2.0);
  EXPECT_NEAR(m.amplitude, 4e-3, 4e-3 * 1e-5);
  EXPECT_NEAR(m.mean, 1e-4, 4e-3 * 1e-5);
  EXPECT_NEAR(m.period, 0.2, 1e-6);
  EXPECT_NEAR(m.frequency(), 5.0, 5.0 * 1e-5);
  EXPECT_NEAR(m.growth, 1.0, 1e-5);
  EXPECT_GE(m.cycles, 9);  // 2 s at 5 Hz: 10 peaks, the last trough may fall after the end
  EXPECT_NEAR(m.largest, 4.1e-3, 4e-3 * 1e-3);  // a sample's value: within 1.2e-4 of the peak's
}

TEST(LimitCycle, GrowthPerCycleIsExpOfSigmaTimesPeriod) {
  // sigma = +-0.8 1/s at 4.3 Hz: a cycle's amplitude changes by exp(sigma T) = 1.2046 or 0.8301.
  // The half peak-to-peak of a peak and the trough half a period later is the amplitude at their
  // midpoint (to (sigma T / 2)^2 / 2 ~ 1 %, the same factor for every cycle), so the ratio of two
  // successive cycles is exp(sigma T) to the refinement's 1e-5.
  for (double sigma : {0.8, -0.8}) {
    const double f = 4.3;
    const Signal s = oscillation(1e-3, f, sigma, 0.0, 3.0);
    const CycleMeasurement m = measure_cycle(s.t, s.x, 1.0);
    EXPECT_NEAR(m.growth, std::exp(sigma / f), 1e-5) << sigma;
    EXPECT_NEAR(m.period, 1.0 / f, 1e-6) << sigma;
  }
}

TEST(LimitCycle, NoOscillation) {
  // A monotone decay has no peak: no cycle, no period, no growth; largest is its value at `from`.
  Signal s;
  for (int i = 0; i <= 1000; ++i) {
    s.t.push_back(i * 1e-3);
    s.x.push_back(2e-3 * std::exp(-3.0 * i * 1e-3));
  }
  const CycleMeasurement m = measure_cycle(s.t, s.x, 0.5);
  EXPECT_EQ(m.cycles, 0);
  EXPECT_EQ(m.amplitude, 0.0);
  EXPECT_EQ(m.period, 0.0);
  EXPECT_EQ(m.growth, 0.0);
  EXPECT_NEAR(m.largest, 2e-3 * std::exp(-1.5), 1e-12);
}

TEST(LimitCycle, OnlyTheWindowCounts) {
  // 3 mm before t = 2 s, 1 mm after: the measurement from 2.1 s sees only the 1 mm cycles.
  Signal s = oscillation(3e-3, 5.0, 0.0, 0.0, 4.0);
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= 2.0) s.x[i] /= 3.0;
  const CycleMeasurement m = measure_cycle(s.t, s.x, 2.1);
  EXPECT_NEAR(m.amplitude, 1e-3, 1e-8);
  EXPECT_NEAR(m.growth, 1.0, 1e-5);
  EXPECT_LT(m.largest, 1.0001e-3);
}

TEST(LimitCycle, NoiseNearThePeaksIsNoCycle) {
  // 5 Hz, 3 mm, with a 60 Hz ripple of 0.3 % of it: near each peak and trough the ripple makes
  // extra extrema (the main slope vanishes there), 0.6 % apart at most, below the 1 % hysteresis.
  // Without it each would count as a cycle of 0.003 mm. The amplitude is then A within the
  // ripple's 0.3 %, the cycles the true 2 s x 5 Hz (the last trough may fall after the end).
  Signal s = oscillation(3e-3, 5.0, 0.0, 0.0, 4.0);
  for (std::size_t i = 0; i < s.t.size(); ++i) s.x[i] += 0.003 * 3e-3 * std::sin(2 * M_PI * 60.0 * s.t[i]);
  const CycleMeasurement m = measure_cycle(s.t, s.x, 2.0);
  EXPECT_NEAR(m.amplitude, 3e-3, 0.0031 * 3e-3);
  EXPECT_GE(m.cycles, 9);
  EXPECT_LE(m.cycles, 10);
  EXPECT_NEAR(m.period, 0.2, 0.2 * 0.01);
}

// The envelope of an oscillation about a mean: half its peak-to-peak over the samples in [from, to),
// the right end excluded; sampled at the peaks (phase pi/2 at 5 Hz every 1 ms) it is exact.
TEST(LimitCycle, HalfRangeIsHalfThePeakToPeakInsideTheInterval) {
  const Signal s = oscillation(4e-3, 5.0, 0.0, 1e-3, 2.0, 1e-3, M_PI / 2);
  EXPECT_NEAR(half_range(s.t, s.x, 0.0, 1.0), 4e-3, 1e-15);
  // [0, 0.1) holds the crest at 0 s (5 mm) but not the trough at 0.1 s: its lowest sample is at 0.099 s.
  const double at_099 = 1e-3 + 4e-3 * std::sin(2 * M_PI * 5.0 * 0.099 + M_PI / 2);
  EXPECT_NEAR(half_range(s.t, s.x, 0.0, 0.1), 0.5 * (5e-3 - at_099), 1e-15);
  EXPECT_EQ(half_range(s.t, s.x, 3.0, 4.0), 0.0);  // no sample there
  const std::vector<double> t{0.0, 1e-3}, x{0.0};
  test::expect_invalid([&] { half_range(t, x, 0.0, 1.0); }, "2 times but 1 values");
}

TEST(LimitCycle, Errors) {
  const std::vector<double> t{0.0, 1e-3, 2e-3}, x{0.0, 1.0};
  test::expect_invalid([&] { measure_cycle(t, x, 0.0); }, "3 times but 2 values");
  const std::vector<double> back{0.0, 2e-3, 1e-3}, x3{0.0, 1.0, 0.0};
  test::expect_invalid([&] { measure_cycle(back, x3, 0.0); }, "not increasing at sample 2");
  test::expect_invalid([&] { measure_cycle(t, x3, 0.0, 0); }, "periods = 0");
}

}  // namespace
}  // namespace wrc
