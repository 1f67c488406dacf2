// SPDX-License-Identifier: Apache-2.0
// EN 14363's sliding mean over 2 m of track at window ends 0.5 m apart (DistanceSlidingMean):
// exact for any quantity linear in the distance however unevenly it is sampled (the window's mean
// of a s + b is the value at its centre), zero for a whole wavelength of a sine, a short peak
// spread over the window, windows only once 2 m have been travelled, jumps at restarts, and bad
// input refused naming the value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/dynamics/sliding_mean.hpp"
#include "expect_invalid.hpp"

namespace wrc {
namespace {

std::vector<DistanceSlidingMean::Mean> means_of(const std::vector<double>& s, double (*f)(double)) {
  DistanceSlidingMean mean;
  std::vector<DistanceSlidingMean::Mean> out;
  for (double x : s) mean.add(x, x / 40.0, f(x), [&](const DistanceSlidingMean::Mean& m) { out.push_back(m); });
  return out;
}

// A linear quantity, sampled at random distances 1 mm to 0.7 m apart (accepted steps are uneven):
// each window's mean is the value at its centre, end - 1 m, to rounding; the ends are every 0.5 m
// from 2 m on (the first sample at 0), and the time is interpolated (t = s / 40 m/s here).
TEST(SlidingMean, ALinearQuantityHasItsCentreValueHoweverItIsSampled) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> gap(1e-3, 0.7);
  std::vector<double> s{0.0};
  while (s.back() < 30.0) s.push_back(s.back() + gap(random));
  const auto line = [](double x) { return 3.0 * x - 5.0; };
  const std::vector<DistanceSlidingMean::Mean> m = means_of(s, +line);
  ASSERT_EQ(m.size(), static_cast<size_t>(std::floor((s.back() - 2.0) / 0.5)) + 1);
  for (size_t k = 0; k < m.size(); ++k) {
    EXPECT_DOUBLE_EQ(m[k].distance, 2.0 + 0.5 * static_cast<double>(k));
    EXPECT_NEAR(m[k].value, line(m[k].distance - 1.0), 1e-12 * 100.0);
    EXPECT_NEAR(m[k].t, m[k].distance / 40.0, 1e-15 * 100.0);
  }
}

// A sine of wavelength 2 m (a wheelset's 2 m oscillation of sum Y) averages out over each window;
// sampled every 1 cm the piecewise-linear interpolant's mean differs from 0 by at most the
// trapezoid rule's error, amplitude * (2 pi h / L)^2 / 12 ~ 8e-5 of the amplitude; bound 1e-4.
TEST(SlidingMean, AWholeWavelengthAveragesOut) {
  std::vector<double> s;
  for (int k = 0; k <= 2000; ++k) s.push_back(0.01 * k + 0.003);
  const auto sine = [](double x) { return 1e4 * std::sin(M_PI * x + 0.4); };
  for (const DistanceSlidingMean::Mean& m : means_of(s, +sine)) EXPECT_NEAR(m.value, 0.0, 1e-4 * 1e4) << m.distance;
}

// A triangular peak 0.1 m wide and 1 high (area 0.05 m) inside a window gives a mean of 0.025:
// the sliding mean spreads a short peak that the instantaneous maximum keeps.
TEST(SlidingMean, AShortPeakIsSpreadOverTheWindow) {
  const auto peak = [](double x) { return std::max(0.0, 1.0 - std::abs(x - 5.25) / 0.05); };
  std::vector<double> s;
  for (int k = 0; k <= 1000; ++k) s.push_back(0.01 * k);
  s.push_back(5.25);
  std::sort(s.begin(), s.end());
  double largest = 0.0;
  for (const DistanceSlidingMean::Mean& m : means_of(s, +peak)) largest = std::max(largest, m.value);
  EXPECT_NEAR(largest, 0.05 / 2.0, 1e-12);
}

// A restart's jump (two samples at one distance) makes a step in the interpolant: a quantity 0
// before 3 m and 1 after has the window ending at 4 m half covered.
TEST(SlidingMean, ARestartsJumpIsAStep) {
  DistanceSlidingMean mean;
  std::vector<DistanceSlidingMean::Mean> out;
  const auto keep = [&](const DistanceSlidingMean::Mean& m) { out.push_back(m); };
  mean.add(0.0, 0.0, 0.0, keep);
  mean.add(3.0, 0.1, 0.0, keep);
  mean.add(3.0, 0.1, 1.0, keep);
  mean.add(6.0, 0.2, 1.0, keep);
  ASSERT_EQ(out.size(), 9u);  // ends 2, 2.5, ..., 6
  EXPECT_DOUBLE_EQ(out[0].value, 0.0);
  EXPECT_DOUBLE_EQ(out[4].distance, 4.0);
  EXPECT_DOUBLE_EQ(out[4].value, 0.5);
  EXPECT_DOUBLE_EQ(out[8].value, 1.0);
}

// Nothing is reported before a whole window lies after the first sample (a run starting at 7.3 m
// reports from 9.5 m on), a non-finite sample is bridged, and going back is refused.
TEST(SlidingMean, WindowsStartAfterTheFirstSampleAndBadInputIsNamed) {
  DistanceSlidingMean mean;
  std::vector<double> ends;
  const auto keep = [&](const DistanceSlidingMean::Mean& m) { ends.push_back(m.distance); };
  mean.add(7.3, 0.0, 1.0, keep);
  mean.add(9.4, 0.1, 1.0, keep);
  EXPECT_TRUE(ends.empty());
  mean.add(9.6, 0.2, NAN, keep);
  EXPECT_TRUE(ends.empty());
  mean.add(10.1, 0.3, 1.0, keep);
  EXPECT_EQ(ends, (std::vector<double>{9.5, 10.0}));
  test::expect_invalid([&] { mean.add(10.0, 0.4, 1.0, keep); }, "distance 10 m comes after 10.1 m");
  test::expect_invalid([&] { DistanceSlidingMean(0.0, 0.5); }, "window 0 [m]");
  test::expect_invalid([&] { DistanceSlidingMean(2.0, NAN); }, "interval nan [m]");
}

}  // namespace
}  // namespace wrc
