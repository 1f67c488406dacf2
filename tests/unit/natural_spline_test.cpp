// SPDX-License-Identifier: Apache-2.0
// The natural interpolating spline of odd degree (track irregularities are interpolated by the
// degree-7 one): exactness for the polynomials it must reproduce, smoothness across the samples,
// the natural end conditions, interpolation accuracy against a cubic spline, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/numerics/cubic_spline.hpp"
#include "core/numerics/natural_spline.hpp"
#include "expect_invalid.hpp"

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Uneven samples on [0, 10]: spacings between 0.5 and 1.1.
std::vector<double> uneven_samples() {
  std::vector<double> x{0.0};
  for (int i = 1; i < 13; ++i) x.push_back(x.back() + 0.8 + 0.3 * std::sin(2.3 * i));
  return x;
}

// A polynomial of degree < m satisfies the natural end conditions (its derivatives m.. are 0), so
// the natural spline of degree 2m - 1 is that polynomial: a cubic for degree 7, a line for
// degree 3 (to the rounding of the coefficients' solve, 2e-12 of the values for degree 9; 1e-11 of
// the values, up to 600 here, and 1e-10 / 1e-8 of them per unit of x for the derivatives).
TEST(NaturalSpline, ReproducesPolynomialsOfDegreeBelowM) {
  const std::vector<double> x = uneven_samples();
  for (int degree : {3, 5, 7, 9}) {
    const int m = (degree + 1) / 2;
    auto f = [m](double t, int k) {  // the polynomial sum_{j<m} (0.3 t)^j / j ... and its derivatives
      double sum = 0.0;
      for (int j = k; j < m; ++j) {
        double falling = 1.0;
        for (int r = 0; r < k; ++r) falling *= j - r;
        sum += falling * std::pow(0.3, j) * std::pow(t, j - k) * (j + 1);
      }
      return sum;
    };
    std::vector<double> y;
    for (double t : x) y.push_back(f(t, 0));
    const NaturalSpline s(degree, x, y);
    for (double t = -0.5; t <= x.back() + 0.5; t += 0.013) {
      const SplineSample v = s.evaluate(t);
      const double size = std::fmax(1.0, std::fabs(f(t, 0)));
      EXPECT_NEAR(v.value, f(t, 0), 1e-11 * size) << "degree " << degree << " at " << t;
      EXPECT_NEAR(v.slope, f(t, 1), 1e-10 * size) << "degree " << degree << " at " << t;
      EXPECT_NEAR(v.second_derivative, f(t, 2), 1e-8 * size) << "degree " << degree << " at " << t;
    }
  }
}

// Rough data: the spline passes through every sample; derivatives 0..p-1 are continuous across
// the interior samples (1e-9 either side: the difference is the next derivative times 2e-9, below
// 1e-6 relative to the derivative's size here), the p-th jumps; derivatives m..2m-2 vanish at
// both ends (relative to the size of that derivative inside).
TEST(NaturalSpline, InterpolatesIsSmoothAndNaturalAtTheEnds) {
  const std::vector<double> x = uneven_samples();
  std::vector<double> y;
  for (std::size_t i = 0; i < x.size(); ++i) y.push_back(std::cos(1.7 * i) + 0.1 * i);
  for (int degree : {3, 5, 7}) {
    const NaturalSpline s(degree, x, y);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s.evaluate(x[i]).value, y[i], 1e-12);
    for (int k = 0; k <= degree; ++k) {
      double scale = 0.0;
      for (double t = x.front(); t <= x.back(); t += 0.01) scale = std::fmax(scale, std::fabs(s.derivative(k, t)));
      for (std::size_t i = 1; i + 1 < x.size(); ++i) {
        const double jump = s.derivative(k, x[i] + 1e-9) - s.derivative(k, x[i] - 1e-9);
        if (k < degree) {
          EXPECT_LT(std::fabs(jump), 1e-6 * scale) << "degree " << degree << ", derivative " << k;
        }
      }
      const int m = (degree + 1) / 2;
      if (k >= m && k <= 2 * m - 2) {
        EXPECT_LT(std::fabs(s.derivative(k, x.front())), 1e-9 * scale) << "degree " << degree << ", derivative " << k;
        EXPECT_LT(std::fabs(s.derivative(k, x.back())), 1e-9 * scale) << "degree " << degree << ", derivative " << k;
      }
    }
    // The p-th derivative is piecewise constant and does jump (the spline is not one polynomial).
    double largest_jump = 0.0;
    for (std::size_t i = 1; i + 1 < x.size(); ++i)
      largest_jump = std::fmax(largest_jump, std::fabs(s.derivative(degree, x[i] + 1e-9) -
                                                       s.derivative(degree, x[i] - 1e-9)));
    EXPECT_GT(largest_jump, 1e-3) << "degree " << degree;
  }
}

// A sine sampled 8 times per wavelength, as a measured track's shortest wavelength is: away from
// the ends the degree-7 spline's value error is below 1e-5 of the amplitude and far below the
// cubic spline's (measured: 4.2e-7 against 1.1e-3), and its error falls like h^8 when the
// spacing halves (measured ratio 400 against 2^8 = 256; the cubic's 17 against 2^4).
TEST(NaturalSpline, InterpolatesASampledSineCloserThanTheCubic) {
  auto max_error = [](int degree, double spacing) {
    std::vector<double> x, y;
    for (double t = 0.0; t <= 40.0 + 1e-9; t += spacing) {
      x.push_back(t);
      y.push_back(std::sin(2 * kPi * t / 8.0));
    }
    double e = 0.0;
    if (degree == 0) {
      const CubicSpline s(x, y);
      for (double t = 15.0; t <= 25.0; t += 0.01) e = std::fmax(e, std::fabs(s.evaluate(t).value - std::sin(2 * kPi * t / 8.0)));
    } else {
      const NaturalSpline s(degree, x, y);
      for (double t = 15.0; t <= 25.0; t += 0.01) e = std::fmax(e, std::fabs(s.evaluate(t).value - std::sin(2 * kPi * t / 8.0)));
    }
    return e;
  };
  const double septic = max_error(7, 1.0), cubic = max_error(0, 1.0);
  std::printf("sine, 8 samples per wavelength: max error degree 7 %.3g, cubic %.3g; halved spacing %.3g, %.3g\n",
              septic, cubic, max_error(7, 0.5), max_error(0, 0.5));
  EXPECT_LT(septic, 1e-5);
  EXPECT_LT(septic, 1e-3 * cubic);
  EXPECT_GT(septic / max_error(7, 0.5), 100.0);
}

TEST(NaturalSpline, RejectsBadInput) {
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> y{0.0, 1.0, 0.0, 1.0, 0.0};
  test::expect_invalid([&] { NaturalSpline(4, x, y); }, {"degree 4"});
  test::expect_invalid([&] { NaturalSpline(11, x, y); }, {"degree 11"});
  test::expect_invalid([&] { NaturalSpline(9, {0.0, 1.0, 2.0, 3.0}, {0.0, 1.0, 0.0, 1.0}); }, {"4 samples", "at least 5"});
  test::expect_invalid([&] { NaturalSpline(7, x, {0.0, 1.0}); }, {"2 values for 5 samples"});
  test::expect_invalid([&] { NaturalSpline(7, {0.0, 1.0, 1.0, 3.0, 4.0}, y); }, {"sample 2", "x = 1"});
  test::expect_invalid([&] { NaturalSpline(7, {0.0, 1.0, NAN, 3.0, 4.0}, y); }, {"sample 2", "not finite"});
  test::expect_invalid([&] { NaturalSpline(7, x, {0.0, 1.0, INFINITY, 1.0, 0.0}); }, {"sample 2", "value inf"});
  test::expect_invalid([&] { NaturalSpline(7, x, y).derivative(8, 1.0); }, {"order 8"});
}

}  // namespace
}  // namespace wrc
