// SPDX-License-Identifier: Apache-2.0
// The rules a run's wheel forces are judged by, each against an independent computation: Nadal's
// limit against the friction-angle form tan(delta - atan mu) and a value worked out by hand,
// Prud'homme's limit in SI units, the S1002 flange angle against the built-in profile's flank, and
// Hertz's maximum pressure against the integral of the ellipsoidal pressure distribution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "core/contact/hertz.hpp"
#include "core/dynamics/safety_limits.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;  // [rad]

void expect_error_naming(const std::function<void()>& f, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one naming '" << text << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

// delta = 70 deg, mu = 0.3: tan 70 deg = 2.747477, (2.747477 - 0.3) / (1 + 0.824243) = 1.341640
// (by hand, 7 digits). The formula equals tan(delta - phi) with the friction angle phi = atan mu
// (the tangent of a difference): that identity is checked to rounding (1e-14 relative) over a
// grid of angles and frictions.
TEST(SafetyLimits, NadalAtKnownValues) {
  EXPECT_NEAR(nadal_limit(70.0 * kDegree, 0.3), 1.341640, 1e-6);
  EXPECT_DOUBLE_EQ(nadal_limit(70.0 * kDegree, 0.0), std::tan(70.0 * kDegree));  // no friction: tan delta
  for (double delta_deg : {30.0, 60.0, 65.0, 70.0, 75.0, 80.0})
    for (double mu : {0.0, 0.1, 0.3, 0.5}) {
      const double delta = delta_deg * kDegree;
      EXPECT_NEAR(nadal_limit(delta, mu), std::tan(delta - std::atan(mu)), 1e-14 * std::tan(delta))
          << delta_deg << " deg, mu " << mu;
    }
  // Less friction or a steeper flange raises the limit.
  EXPECT_GT(nadal_limit(72.0 * kDegree, 0.3), nadal_limit(70.0 * kDegree, 0.3));
  EXPECT_GT(nadal_limit(70.0 * kDegree, 0.2), nadal_limit(70.0 * kDegree, 0.3));
}

TEST(SafetyLimits, NadalRefusesBadInputNamingIt) {
  expect_error_naming([] { nadal_limit(0.0, 0.3); }, "flange_angle = 0 rad is outside (0, pi/2)");
  expect_error_naming([] { nadal_limit(kMaxFlangeAngle, 0.3); }, "flange_angle = 1.5708");
  expect_error_naming([] { nadal_limit(-0.5, 0.3); }, "flange_angle = -0.5");
  expect_error_naming([] { nadal_limit(std::nan(""), 0.3); }, "flange_angle = nan");
  expect_error_naming([] { nadal_limit(1.2, -0.1); }, "friction = -0.1");
}

// 1e4 N + P / 3: an axle load of 170 kN (17 t) gives 10 kN + 56.667 kN = 66.667 kN.
TEST(SafetyLimits, PrudhommeInSi) {
  EXPECT_NEAR(prudhomme_limit(170e3), 66666.666666666667, 1e-9);
  EXPECT_DOUBLE_EQ(prudhomme_limit(3.0), 1e4 + 1.0);
  expect_error_naming([] { prudhomme_limit(0.0); }, "axle load P = 0 N");
  expect_error_naming([] { prudhomme_limit(-5.0); }, "axle load P = -5 N");
}

// The default flange angle is the steepest slope of the built-in S1002 wheel: the largest
// atan(-dF/ds) on the flange flank (the flange back, where dF/ds > 0, does not count). The flank is
// a straight line of slope -2.747477419, tan 70 deg to 10 digits: the angle agrees within 1e-9 rad,
// the scan's grid (0.01 mm) sits on the line for many points so it sees the largest slope exactly.
TEST(SafetyLimits, DefaultFlangeAngleIsS1002s) {
  EXPECT_DOUBLE_EQ(kS1002FlangeAngle, 70.0 * kDegree);
  const ProfilePtr wheel = make_profile("S1002", ProfileSide::kWheel);
  double steepest = 0.0;
  const int n = 13000;
  for (int k = 0; k <= n; ++k) {
    const double s = wheel->lower() + (wheel->upper() - wheel->lower()) * k / n;
    steepest = std::max(steepest, std::atan(-wheel->evaluate(s).slope));
  }
  EXPECT_NEAR(steepest, kS1002FlangeAngle, 1e-9);
}

// p0 = 3 N / (2 pi a b): the pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2) integrated over the ellipse
// (midpoint rule in the scaled radius, 1e5 intervals: error below 1e-6 relative at the square-root
// edge) gives back N; hertz_from_force reports the same p0. A tread contact: A = 1 / (2 r0) of a
// 0.46 m wheel, B = 1 / (2 * 0.3 m) of the rail head, 85 kN: p0 of about 1 GPa.
TEST(SafetyLimits, MaxPressureIsHertzs) {
  const HertzContact c = hertz_from_force(1.0 / 0.92, 1.0 / 0.6, contact_modulus(8.2e10, 0.28), 85e3);
  const double p0 = hertz_max_pressure(c.normal_force, c.a, c.b);
  EXPECT_EQ(p0, c.max_pressure);
  const int n = 100000;
  double integral = 0.0;  // int_0^1 r sqrt(1 - r^2) dr, exactly 1/3
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) / n;
    integral += r * std::sqrt(1.0 - r * r) / n;
  }
  const double force = 2.0 * kPi * c.a * c.b * p0 * integral;
  EXPECT_NEAR(force, 85e3, 1e-6 * 85e3);
  EXPECT_GT(p0, 7e8);
  EXPECT_LT(p0, 1.5e9);
  EXPECT_EQ(hertz_max_pressure(0.0, 0.0, 0.0), 0.0);
  expect_error_naming([] { hertz_max_pressure(-1.0, 1e-3, 1e-3); }, "N = -1 N");
  expect_error_naming([] { hertz_max_pressure(1.0, 0.0, 1e-3); }, "a = 0 m");
}

}  // namespace
}  // namespace wrc
