// SPDX-License-Identifier: Apache-2.0
// Unit tests of the complete elliptic integrals and the Hertz solution (services/core/contact).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/contact/elliptic.hpp"
#include "core/contact/hertz.hpp"
#include "expect_invalid.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kEstar = wrc::contact_modulus(8.2e10, 0.28);  // G / (1 - nu) [Pa]

using wrc::test::expect_invalid;

// Verifies K and E at reference points: k = 0 (pi/2 both), k = 1/sqrt(2) (K and E to 16 digits from
// DLMF 19.20 / Gauss's lemniscate constant), and Legendre's relation E K' + E' K - K K' = pi/2 at
// k' = 0.3, which ties the two kinds together. 1e-15 relative is a few ulps: the AGM is exact to rounding.
TEST(HertzElliptic, ReferenceValuesAndLegendreRelation) {
  const auto zero = wrc::complete_elliptic_integrals(0.0);
  EXPECT_NEAR(zero.K, kPi / 2, 1e-15);
  EXPECT_NEAR(zero.E, kPi / 2, 1e-15);
  EXPECT_EQ(zero.K_minus_E, 0.0);
  const auto half = wrc::complete_elliptic_integrals(std::sqrt(0.5));
  EXPECT_NEAR(half.K, 1.8540746773013719, 2e-15 * 1.85);
  EXPECT_NEAR(half.E, 1.3506438810476755, 2e-15 * 1.35);
  const double kc = 0.3;
  const auto e1 = wrc::complete_elliptic_integrals_from_complement(kc);
  const auto e2 = wrc::complete_elliptic_integrals_from_complement(std::sqrt(1 - kc * kc));
  EXPECT_NEAR(e1.E * e2.K + e2.E * e1.K - e1.K * e2.K, kPi / 2, 4e-15);
}

// Verifies robustness for k -> 1: with k' = 1e-6 the expansions K = ln(4/k') + (k'^2/4)(ln(4/k') - 1)
// and E = 1 + (k'^2/2)(ln(4/k') - 1/2) are exact up to O(k'^4 ln k') ~ 1e-23, so both must agree to
// 1e-13 relative (rounding of the AGM only).
// Also verifies the cancellation-free differences for small k = 1e-3 against their series
// K - E = pi k^2/4 (1 + 3k^2/8 + 15k^4/64), E - k'^2 K = pi k^2/4 (1 + k^2/8 + 3k^4/64)
// (next terms O(k^6) ~ 1e-18 relative), to 1e-14 relative: forming them as K - E would lose 6 digits.
TEST(HertzElliptic, NearlyDegenerateAndNearlyCircular) {
  const auto d = wrc::complete_elliptic_integrals_from_complement(1e-6);
  EXPECT_NEAR(d.K, std::log(4e6) + 0.25e-12 * (std::log(4e6) - 1.0), 1e-13 * d.K);
  EXPECT_NEAR(d.E, 1.0 + 0.5e-12 * (std::log(4e6) - 0.5), 1e-13);
  const double k = 1e-3;
  const auto s = wrc::complete_elliptic_integrals(k);
  EXPECT_NEAR(s.K_minus_E, kPi * k * k / 4 * (1 + 3 * k * k / 8 + 15 * k * k * k * k / 64), 1e-14 * kPi * k * k / 4);
  EXPECT_NEAR(s.E_minus_kc2_K, kPi * k * k / 4 * (1 + k * k / 8 + 3 * k * k * k * k / 64), 1e-14 * kPi * k * k / 4);
}

// Verifies the sphere limit A = B = 1/(2R): a = b = (3NR/(4E*))^{1/3}, delta = a^2/R,
// N = (4/3) E* sqrt(R) delta^{3/2}. Closed forms, so agreement to 1e-12 relative (rounding only).
TEST(HertzContact, SphereLimit) {
  const double R = 0.46, N = 5e4;
  const auto c = wrc::hertz_from_force(1 / (2 * R), 1 / (2 * R), kEstar, N);
  const double a = std::cbrt(3 * N * R / (4 * kEstar));
  EXPECT_NEAR(c.a, a, 1e-12 * a);
  EXPECT_NEAR(c.b, a, 1e-12 * a);
  EXPECT_NEAR(c.penetration, a * a / R, 1e-12 * a * a / R);
  EXPECT_NEAR(c.stiffness, 4.0 / 3.0 * kEstar * std::sqrt(R), 1e-12 * c.stiffness);
  EXPECT_NEAR(c.max_pressure, 3 * N / (2 * kPi * a * a), 1e-12 * c.max_pressure);
  EXPECT_DOUBLE_EQ(c.shape.eccentricity, 0.0);
}

// Verifies m, n and a/b against the table of Hertz coefficients versus theta (docs/contact-mechanics.md)
// (cos theta = (B - A)/(A + B)), B > A. The table has 4 significant digits (rounding <= 0.05 %), so
// a 0.2 % tolerance leaves margin; theta = 1 deg (a/b = 281) is beyond a/b = 50 and included.
TEST(HertzContact, CoefficientsMatchTable) {
  struct Row { double theta_deg, m, n, a_over_b; };
  const Row rows[] = {{1, 36.93, 0.1313, 281.3}, {2, 22.24, 0.1692, 131.5}, {5, 11.24, 0.2381, 47.19},
                      {10, 6.612, 0.3110, 21.26}, {15, 4.808, 0.3657, 13.15}, {20, 3.816, 0.4121, 9.259},
                      {30, 2.731, 0.4931, 5.538}, {40, 2.136, 0.5673, 3.765}, {50, 1.754, 0.6407, 2.738},
                      {60, 1.486, 0.7171, 2.072}, {70, 1.285, 0.7999, 1.607}, {80, 1.128, 0.8927, 1.263},
                      {85, 1.061, 0.9442, 1.124}};
  for (const Row& r : rows) {
    const double ct = std::cos(r.theta_deg * kPi / 180);
    const double A = 1.0, B = (1 + ct) / (1 - ct);
    const auto s = wrc::hertz_shape(A, B);
    EXPECT_NEAR(s.m, r.m, 2e-3 * r.m) << "theta " << r.theta_deg;
    EXPECT_NEAR(s.n, r.n, 2e-3 * r.n) << "theta " << r.theta_deg;
    EXPECT_NEAR(s.axis_ratio, r.a_over_b, 2e-3 * r.a_over_b) << "theta " << r.theta_deg;
    // Swapped curvatures swap the axes: a becomes the short one.
    const auto t = wrc::hertz_shape(B, A);
    EXPECT_NEAR(t.m, s.n, 1e-13 * s.n);
    EXPECT_NEAR(t.n, s.m, 1e-13 * s.m);
  }
}

// Verifies the order-of-magnitude example of docs/contact-mechanics.md, "Hertz": N = 80 kN on a 0.46 m
// wheel and an R300 rail crown gives a = 6.68 mm, b = 5.02 mm, p0 = 1.14 GPa, delta = 90 um. Tolerances are
// half a unit of the last printed digit plus margin: 0.1 % for a and b (3 digits), 0.5 % for p0, 0.7 % for
// delta (2 digits).
TEST(HertzContact, OrderOfMagnitudeExample) {
  const auto c = wrc::hertz_from_force(0.5 / 0.46, 0.5 / 0.30, kEstar, 80e3);
  EXPECT_NEAR(c.a, 6.68e-3, 1e-3 * 6.68e-3);
  EXPECT_NEAR(c.b, 5.02e-3, 1e-3 * 5.02e-3);
  EXPECT_NEAR(c.max_pressure, 1.14e9, 5e-3 * 1.14e9);
  EXPECT_NEAR(c.penetration, 90e-6, 7e-3 * 90e-6);
  // The stiffness reproduces the load (C_H is an independent formula, not derived from delta here).
  EXPECT_NEAR(c.stiffness * std::pow(c.penetration, 1.5), 80e3, 1e-10 * 80e3);
  // p0 is 3/2 of the mean pressure N / (pi a b) by definition.
  EXPECT_NEAR(c.max_pressure, 1.5 * 80e3 / (kPi * c.a * c.b), 1e-12 * c.max_pressure);
}

// Verifies the inverse law for elongated and wide ellipses: from a force, take the penetration, solve
// for the force again: N, a, b must come back to rounding (1e-12), since both paths are closed forms
// on the same shape.
TEST(HertzContact, ForcePenetrationRoundTrip) {
  const double ratios[] = {1.0 / 3000, 0.02, 0.3, 1.0, 7.0, 50.0, 3000.0};
  for (double ratio : ratios) {
    const auto shape = wrc::hertz_shape(1.0, ratio);
    for (double N : {1.0, 1e3, 1.2e5}) {
      const auto f = wrc::hertz_from_force(shape, kEstar, N);
      const auto p = wrc::hertz_from_penetration(shape, kEstar, f.penetration);
      EXPECT_NEAR(p.normal_force, N, 1e-12 * N) << "B/A " << ratio;
      EXPECT_NEAR(p.a, f.a, 1e-12 * f.a);
      EXPECT_NEAR(p.b, f.b, 1e-12 * f.b);
      EXPECT_NEAR(p.max_pressure, f.max_pressure, 1e-11 * f.max_pressure);
    }
  }
  const auto zero = wrc::hertz_from_penetration(wrc::hertz_shape(1, 2), kEstar, 0.0);
  EXPECT_EQ(zero.normal_force, 0.0);
  EXPECT_EQ(zero.a, 0.0);
}

// Verifies the shape solver over B/A from 1/5000 to 5000 (a/b beyond 1/50 .. 50): a/b strictly increases
// with B/A, the range covers 1/50 .. 50, and the solution satisfies the axis-ratio equation
// B/A = ((a/b)^2 E - K)/(K - E) to 1e-12 relative (the solver stops at 1e-15 in ln k'; the equation's
// sensitivity d ln(B/A)/d ln(a/b) is about 1.6, and K, E carry ~1e-15).
TEST(HertzContact, AxisRatioMonotoneAndSolvesEquation) {
  double previous = 0;
  double smallest = 1e300, largest = 0;
  for (int i = -370; i <= 370; ++i) {
    const double ratio = std::pow(10.0, i / 100.0);  // B/A
    const auto s = wrc::hertz_shape(2.0, 2.0 * ratio);
    EXPECT_GT(s.axis_ratio, previous) << "B/A " << ratio;
    previous = s.axis_ratio;
    smallest = std::min(smallest, s.axis_ratio);
    largest = std::max(largest, s.axis_ratio);
    if (ratio > 1.0 + 1e-12 || ratio < 1.0 - 1e-12) {
      const double k = 1 / std::max(s.axis_ratio, 1 / s.axis_ratio);  // minor / major
      const double big = std::max(s.A, s.B) / std::min(s.A, s.B);
      const double formula = (s.E - k * k * s.K) / (k * k * (s.K - s.E));
      EXPECT_NEAR(formula, big, 1e-10 * big) << "B/A " << ratio;
    }
  }
  EXPECT_LT(smallest, 1.0 / 50);
  EXPECT_GT(largest, 50.0);
  // Nearly circular: the series B/A = 1 + (3/4) e^2 + O(e^4), a/b = 1 + e^2/2 + O(e^4) give
  // a/b - 1 = (2/3)(B/A - 1) = 6.667e-10 for B/A = 1 + 1e-9. The solver works in ln(b/a) ~ -3e-10 and
  // must keep its relative accuracy there: 1e-4 relative on a/b - 1 (O(e^2) series error ~1e-9, solver
  // tolerance ~1e-15 absolute in ln(b/a), i.e. 3e-6 relative).
  const auto near = wrc::hertz_shape(1.0, 1.0 + 1e-9);
  EXPECT_NEAR(near.axis_ratio - 1.0, 2.0 / 3.0 * 1e-9, 1e-4 * 2.0 / 3.0 * 1e-9);
}

// Verifies the error contract: non-positive or NaN curvatures, a negative or NaN force or penetration
// and an invalid material throw std::invalid_argument naming the value.
TEST(HertzContact, RejectsInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_invalid([] { wrc::hertz_shape(0.0, 1.0); }, "A = 0");
  expect_invalid([] { wrc::hertz_shape(1.0, -2.5); }, "B = -2.5");
  expect_invalid([&] { wrc::hertz_shape(nan, 1.0); }, "A = nan");
  expect_invalid([] { wrc::hertz_from_force(1.0, 2.0, kEstar, -5.0); }, "N = -5");
  expect_invalid([&] { wrc::hertz_from_force(1.0, 2.0, kEstar, nan); }, "N = nan");
  expect_invalid([&] { wrc::hertz_from_penetration(wrc::hertz_shape(1, 2), kEstar, -1e-6); }, "delta = -1e-06");
  expect_invalid([] { wrc::contact_modulus(-1.0, 0.28); }, "G = -1");
  expect_invalid([] { wrc::contact_modulus(8e10, 0.6); }, "nu = 0.6");
  expect_invalid([] { wrc::complete_elliptic_integrals(1.0); }, "k = 1");
}

}  // namespace
