// SPDX-License-Identifier: Apache-2.0
// Conic wheel on a circular rail head: the one case with a closed-form contact point. Checks the
// curve C, the potential-point search and the rigid-wheelset solver against it.
//
// Set-up: no rail inclination, gauge measured at the top of rail (gauge depth 0) and gauge 1.5 m, so
// the crown tops lie at y = +-0.75 m, right below the taping lines. Wheel F(s) = -lambda*s.
// Zero yaw: the left wheel's bottom generator has track slope tan(gamma + phi) (gamma = atan
// lambda), the circle has that slope at y_c - rho*sin(gamma + phi); the right wheel mirrors with
// gamma - phi. Everything else follows by elementary geometry (derivation in the helpers below).

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/conicity.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

constexpr double kLambda = 0.05;  // cone slope
constexpr double kRho = 0.1;      // rail head radius [m]

TrackParameters cone_track() {
  TrackParameters t;
  t.gauge = 1.5;
  t.gauge_depth = 0.0;
  t.inclination = 0.0;
  return t;
}

WheelsetGeometry cone_on_circle() {
  return WheelsetGeometry(make_profile("conic:0.05", ProfileSide::kWheel), make_profile("circle:0.1", ProfileSide::kRail),
                          cone_track());
}

struct ClosedForm {
  double s, distance, angle, radius, y_rail;
};

// Closed-form contact of one wheel at (y, z, roll), zero yaw.
ClosedForm closed_form(WheelSide side, double y, double z, double roll) {
  const TrackParameters t = cone_track();
  const double a = t.taping_half_distance(), r0 = t.nominal_radius, yc = 0.75;
  const double gamma = std::atan(kLambda);
  const double c = std::cos(roll), sn = std::sin(roll);
  ClosedForm f;
  if (side == WheelSide::kLeft) {
    f.angle = gamma + roll;
    f.y_rail = yc - kRho * std::sin(f.angle);
    f.s = (f.y_rail - y - a * c - r0 * sn) / (c - kLambda * sn);
    const double z_wheel = z + (a + f.s) * sn - (r0 - kLambda * f.s) * c;
    f.distance = z_wheel - (-kRho + kRho * std::cos(f.angle));
  } else {
    f.angle = gamma - roll;
    f.y_rail = -yc + kRho * std::sin(f.angle);
    f.s = (f.y_rail - y + a * c - r0 * sn) / (-c - kLambda * sn);
    const double z_wheel = z - (a + f.s) * sn - (r0 - kLambda * f.s) * c;
    f.distance = z_wheel - (-kRho + kRho * std::cos(f.angle));
  }
  f.radius = r0 - kLambda * f.s;
  return f;
}

// Small shifts, to first order in y and roll (derivation: the left contact moves along the cone by
// s_L = -rho sin(gamma) - y - K roll and the right by s_R = -rho sin(gamma) + y + K roll, with
// K = rho cos(gamma) + r0 the lever of roll about the rail head centre; equal distances of both
// wheels give 2 a roll = 2 lambda (y + K roll), a = taping half distance):
//   roll = lambda y / (a - lambda K),   delta_r = -lambda (s_L - s_R) = 2 lambda y a / (a - lambda K).
double small_shift_lever() {
  return kRho * std::cos(std::atan(kLambda)) + cone_track().nominal_radius;
}
double small_shift_roll_per_y() {
  const double a = cone_track().taping_half_distance();
  return kLambda / (a - kLambda * small_shift_lever());
}
double small_shift_delta_r_per_y() {
  const double a = cone_track().taping_half_distance();
  return 2 * kLambda * a / (a - kLambda * small_shift_lever());
}

// One potential common point per wheel, at the closed-form position to 1e-10 m (root tolerance
// 1e-12 m, rail inversion to 1e-14 m), with the closed-form distance, contact angle and radius.
TEST(GeometryConeOnCircle, PotentialPointMatchesClosedForm) {
  const WheelsetGeometry g = cone_on_circle();
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    for (double y : {-0.008, -0.003, 0.0, 0.002, 0.0075}) {
      for (double roll : {-0.01, 0.0, 0.004}) {
        WheelsetPose pose;
        pose.y = y;
        pose.z = 0.4601;
        pose.roll = roll;
        const auto points = g.potential_points(side, pose);
        ASSERT_EQ(points.size(), 1u) << side_name(side) << " y=" << y << " roll=" << roll;
        const ContactPoint& p = points[0];
        const ClosedForm f = closed_form(side, y, pose.z, roll);
        EXPECT_TRUE(p.is_minimum);
        EXPECT_NEAR(p.s, f.s, 1e-10);
        EXPECT_NEAR(p.distance, f.distance, 1e-10);
        EXPECT_NEAR(p.contact_angle, f.angle, 1e-9);
        EXPECT_NEAR(p.rolling_radius, f.radius, 1e-10);
        EXPECT_NEAR(p.rail_point.y(), f.y_rail, 1e-10);
        // Curvatures: cone generator is straight, circle has 1/rho, Meusnier for the wheel.
        EXPECT_NEAR(p.wheel_curvature_lateral, 0.0, 1e-9);
        EXPECT_NEAR(p.rail_curvature_lateral, 1.0 / kRho, 1e-9);
        EXPECT_NEAR(p.wheel_curvature_rolling, 1.0 / (f.radius * std::sqrt(1 + kLambda * kLambda)), 1e-9);
        // The common normal is the rail normal, tilted by the contact angle towards the track centre.
        const double sigma = side_sign(side);
        EXPECT_NEAR(p.normal.y(), -sigma * std::sin(f.angle), 1e-9);
        EXPECT_NEAR(p.normal.z(), std::cos(f.angle), 1e-9);
      }
    }
  }
}

// Rigid wheelset: roll and height from an independent bisection on the closed-form distances;
// agreement to 1e-10 (the solver's height tolerance is 1e-12 m, roll enters with lever 0.75 m).
TEST(GeometryConeOnCircle, RigidWheelsetMatchesClosedForm) {
  const WheelsetGeometry g = cone_on_circle();
  const RigidWheelsetSolver solver(g);
  for (double y : {-0.006, -0.001, 0.0, 0.0025, 0.007}) {
    double lo = -0.05, hi = 0.05;
    auto residual = [&](double roll) {
      return closed_form(WheelSide::kLeft, y, 0, roll).distance - closed_form(WheelSide::kRight, y, 0, roll).distance;
    };
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (residual(mid) > 0 ? hi : lo) = mid;
    }
    const double roll = 0.5 * (lo + hi);
    const double z = -closed_form(WheelSide::kLeft, y, 0, roll).distance;
    const RigidContact c = solver.solve(y, 0.0);
    EXPECT_NEAR(c.pose.roll, roll, 1e-10) << y;
    EXPECT_NEAR(c.pose.z, z, 1e-10) << y;
    EXPECT_NEAR(c.left().rolling_radius, closed_form(WheelSide::kLeft, y, z, roll).radius, 1e-10);
    EXPECT_NEAR(c.right().rolling_radius, closed_form(WheelSide::kRight, y, z, roll).radius, 1e-10);
    EXPECT_NEAR(c.left().distance, 0.0, 1e-11);
    EXPECT_NEAR(c.right().distance, 0.0, 1e-11);
    // Small-shift limit (small_shift_* above): delta_r = 2 lambda y a / (a - lambda K) = 0.10388 y
    // and roll = lambda y / (a - lambda K) = 0.06925 y, to 1e-4 relative. The formulas are first
    // order; what they neglect are products of two small quantities (lambda roll <= 2.5e-5,
    // lambda rho sin(gamma) / a = 3.3e-4 before the two wheels' terms cancel); observed: 1.7e-5.
    if (y != 0.0) {
      EXPECT_NEAR(c.delta_r() / y, small_shift_delta_r_per_y(), 1e-4 * small_shift_delta_r_per_y()) << y;
      EXPECT_NEAR(c.pose.roll / y, small_shift_roll_per_y(), 1e-4 * small_shift_roll_per_y()) << y;
    }
  }
}

// Warm start from a neighbouring solution gives the cold-start result, to the solver's tolerance
// (height residual 1e-12 m, i.e. roll to about 1e-12 m / 1.5 m).
TEST(GeometryConeOnCircle, WarmStartEqualsColdStart) {
  const WheelsetGeometry g = cone_on_circle();
  const RigidWheelsetSolver solver(g);
  const RigidContact near = solver.solve(0.003, 0.0);
  const RigidContact warm = solver.solve(0.0031, 0.0, near);
  const RigidContact cold = solver.solve(0.0031, 0.0);
  EXPECT_NEAR(warm.pose.roll, cold.pose.roll, 2e-12);
  EXPECT_NEAR(warm.pose.z, cold.pose.z, 1e-12);
  EXPECT_NEAR(warm.left().s, cold.left().s, 1e-10);
}

// Equivalent conicity of the cone: delta_r is linear in y to 1e-7 relative over +-7 mm (see
// above), and the harmonic linearisation of a linear delta_r = k y gives exactly k / 2, so
// lambda_e = lambda a / (a - lambda K) = 1.0388 lambda, to the 1e-4 of the small-shift formula.
// The factor above 1 is the roll: it carries each contact K roll further along the tread.
// Knife-edge limit (circle:0.0001, K -> r0): lambda a / (a - lambda r0) = 1.0317 lambda; without
// the roll's shift it would be lambda itself.
TEST(GeometryConeOnCircle, EquivalentConicityMatchesClosedForm) {
  const WheelsetGeometry g = cone_on_circle();  // the solver keeps a reference to it
  const RigidWheelsetSolver solver(g);
  for (double amplitude : {0.002, 0.006}) {
    EXPECT_NEAR(equivalent_conicity(solver, amplitude), 0.5 * small_shift_delta_r_per_y(),
                1e-4 * 0.5 * small_shift_delta_r_per_y())
        << amplitude;
  }
  const WheelsetGeometry knife(make_profile("conic:0.05", ProfileSide::kWheel),
                               make_profile("circle:0.0001", ProfileSide::kRail), cone_track());
  const RigidWheelsetSolver knife_solver(knife);
  const double a = cone_track().taping_half_distance(), r0 = cone_track().nominal_radius;
  const double knife_edge = kLambda * a / (a - kLambda * r0);
  EXPECT_NEAR(equivalent_conicity(knife_solver, 0.003), knife_edge, 1e-4 * knife_edge);
}

}  // namespace
}  // namespace wrc
