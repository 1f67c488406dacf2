// SPDX-License-Identifier: Apache-2.0
// Y, Q, the creep forces, T gamma and p_max of one wheel: from
// patches whose sums are worked out on paper (docs/run-quantities.md's definitions), and on a real
// model's contact (one-point, S1002 on UIC60) against the model's own resultant. And the physical
// signs: in flange contact the flanging wheel's Y and Y/Q are positive and large.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/dynamics/wheel_forces.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/models/contact_model_factory.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The one-point model's rigid contact at lateral shift y [m] and yaw [rad], with roll and height
// from the rigid wheelset (both wheels touching), moving and loaded as in the benchmark.
ContactResult contact_at(double y, double yaw) {
  const auto geometry = test::s1002_uic60_geometry();
  const RigidContact rigid = RigidWheelsetSolver(*geometry).solve(y, yaw);
  ContactQuery q;
  q.pose = rigid.pose;
  q.y_dot = 0.02;      // [m/s]
  q.yaw_dot = 0.01;    // [rad/s]
  q.speed = 30.0;
  q.spin_rate = q.speed / 0.46 * (1.0 + 2e-4);  // a little longitudinal creepage [rad/s]
  q.normal_load = {7.8e4, 9.3e4};
  return make_contact_model("onepoint", geometry)->evaluate(q);
}

// A patch of wheel side with contact angle delta given by its sine and cosine (normal from the
// rail into the wheel, in the y-z plane: no yaw, so t1 = e_x and t2 = n x e_x), its normal and
// creep forces [N], creepages [-] and semi-axes [m].
ContactPatch patch(WheelSide side, double sin_delta, double cos_delta, double n, double fx, double fy, double xi_x,
                   double xi_y, double a, double b) {
  ContactPatch p;
  p.point.side = side;
  p.point.normal = Eigen::Vector3d(0.0, side == WheelSide::kLeft ? -sin_delta : sin_delta, cos_delta);
  p.normal_force = n;
  p.forces.fx = fx;
  p.forces.fy = fy;
  p.creepages.longitudinal = xi_x;
  p.creepages.lateral = xi_y;
  p.a = a;
  p.b = b;
  return p;
}

// Two wheels whose read-offs are worked out on paper (docs/run-quantities.md's definitions), with
// angles whose sine and cosine are exact in binary (3-4-5 triangles), so every expected value is
// exact up to the rounding of a few products:
// - right wheel, one flange patch, sin 0.6, cos 0.8: n = (0, 0.6, 0.8), t2 = n x e_x = (0, 0.8,
//   -0.6). N = 50 kN, fx = 5 kN, fy = 10 kN: F_y = 30 + 8 = 38 kN = Y (towards the centre on the
//   right wheel), Q = F_z = 40 - 6 = 34 kN, T gamma = |5e3 1e-3| + |1e4 (-2e-3)| = 25 N, p_max =
//   3 N / (2 pi a b) with a = 6 mm, b = 4 mm: 3.125e9 / pi Pa.
// - left wheel, a tread patch (n = e_z, t2 = (0, 1, 0)) and a flange patch (sin 0.6: n = (0,
//   -0.6, 0.8), t2 = (0, 0.8, 0.6)): N = 40 + 20 kN, fy = 2 and -5 kN: F_y = 2 - 12 - 4 = -14 kN, so
//   Y = +14 kN; Q = 40 + 16 - 3 = 53 kN; the normal resultant per unit N is (0, -12, 56) / 60;
//   T gamma = |1e3 5e-4| + |2e3 1e-3| + |-1e3 (-1e-3)| + |-5e3 (-3e-3)| = 0.5 + 2 + 1 + 15 = 18.5 N;
//   p_max from the smaller flange patch, 3 20e3 / (2 pi 3e-3 2e-3) = 5e9 / pi Pa.
TEST(WheelForces, ReadOffsOfPatchesWorkedOutOnPaper) {
  ContactResult c;
  c.patches = {patch(WheelSide::kLeft, 0.0, 1.0, 40e3, 1e3, 2e3, 5e-4, 1e-3, 6e-3, 4e-3),
               patch(WheelSide::kLeft, 0.6, 0.8, 20e3, -1e3, -5e3, -1e-3, -3e-3, 3e-3, 2e-3),
               patch(WheelSide::kRight, 0.6, 0.8, 50e3, 5e3, 10e3, 1e-3, -2e-3, 6e-3, 4e-3)};
  std::array<WheelOutput, 2> out;
  std::array<WheelForces, 2> f;
  for (int wheel = 0; wheel < 2; ++wheel) {
    f[static_cast<size_t>(wheel)] = wheel_forces(c, wheel);
    set_force_outputs(f[static_cast<size_t>(wheel)], f[static_cast<size_t>(wheel)].normal_force, wheel,
                      out[static_cast<size_t>(wheel)]);
  }
  const double tol = 1e-9;  // [N]: products of numbers of a few significant digits, rounded
  EXPECT_NEAR(f[1].normal_force, 50e3, tol);
  EXPECT_NEAR(out[1].lateral_force, 38e3, tol);
  EXPECT_NEAR(out[1].vertical_force, 34e3, tol);
  EXPECT_NEAR(out[1].y_over_q(), 38.0 / 34.0, 1e-15);
  EXPECT_NEAR(out[1].creep_force_x, 5e3, tol);
  EXPECT_NEAR(out[1].creep_force_y, 10e3, tol);
  EXPECT_NEAR(out[1].wear_number, 25.0, 1e-12);
  EXPECT_NEAR(out[1].max_pressure, 3.125e9 / kPi, 1e-6);
  EXPECT_NEAR(f[0].normal_force, 60e3, tol);
  EXPECT_NEAR(out[0].lateral_force, 14e3, tol);
  EXPECT_NEAR(out[0].vertical_force, 53e3, tol);
  EXPECT_NEAR(out[0].creep_force_x, 0.0, tol);
  EXPECT_NEAR(out[0].creep_force_y, -3e3, tol);
  EXPECT_NEAR(out[0].wear_number, 18.5, 1e-12);
  EXPECT_NEAR(out[0].max_pressure, 5e9 / kPi, 1e-6);
  EXPECT_NEAR((f[0].normal_direction - Eigen::Vector3d(0.0, -0.2, 56.0 / 60.0)).norm(), 0.0, 1e-15);
  // The track-shift force sum Y = Y_L - Y_R: 14 - 38 kN.
  EXPECT_NEAR(track_shift_force(out[0].lateral_force, out[1].lateral_force), -24e3, tol);
}

// On a real model's contact (one-point, S1002 on UIC60, displaced, yawed, moving: every creepage
// non-zero, t1 not along e_x), both wheels' forces add up to the model's own resultant (its
// add_to_resultant), to 1e-9 of the load, and T gamma is positive: the sums agree with the
// model's in a general configuration.
TEST(WheelForces, BothWheelsAddUpToTheModelsResultant) {
  for (const double y : {-2e-3, 3e-3}) {
    const ContactResult c = contact_at(y, 1.5e-3);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int wheel = 0; wheel < 2; ++wheel) {
      const WheelForces f = wheel_forces(c, wheel);
      ASSERT_GT(f.normal_force, 0.0);
      EXPECT_GT(f.wear_number, 0.0) << "the state must have creepage for the test to mean something";
      total += f.force(f.normal_force);
    }
    EXPECT_NEAR((total - c.force).norm(), 0.0, 1e-9 * 1.71e5) << "y " << y;
  }
}

// The right wheel in flange contact (y = -7 mm: beyond the flange-root jump, contact angle well
// above the tread's 0.12 rad): the rail pushes it towards the track centre, so Y_right > 0, and
// with the creep force at most mu N in the contact plane (no yaw: t1 is horizontal) Y/Q lies
// between tan(delta - atan mu) and tan(delta + atan mu); the left wheel on its tread carries a
// small Y. The track-shift force Y_L - Y_R is then negative: the
// wheelset pushes the track towards the right (-y).
TEST(WheelForces, FlangeContactSigns) {
  const ContactResult c = contact_at(-7e-3, 0.0);
  ASSERT_GT(c.wheels[1].contact_angle, 0.3);
  std::array<WheelOutput, 2> out;
  for (int wheel = 0; wheel < 2; ++wheel) {
    const WheelForces f = wheel_forces(c, wheel);
    set_force_outputs(f, f.normal_force, wheel, out[static_cast<size_t>(wheel)]);
  }
  EXPECT_GT(out[1].lateral_force, 0.0);
  const double delta = c.wheels[1].contact_angle, phi = std::atan(0.3);
  EXPECT_GT(out[1].y_over_q(), std::tan(delta - phi) - 1e-9);
  EXPECT_LT(out[1].y_over_q(), std::tan(delta + phi) + 1e-9);
  EXPECT_LT(std::abs(out[0].y_over_q()), 0.2);
  EXPECT_LT(track_shift_force(out[0].lateral_force, out[1].lateral_force), 0.0);
  EXPECT_GT(out[1].vertical_force, 0.0);
}

// A normal force other than the patches' (the rigid run's constraint force at an output between
// steps) scales the normal part only: Q(N) - Q(N_p) = (N - N_p) n_z.
TEST(WheelForces, NormalForceAppliedAlongTheNormal) {
  const ContactResult c = contact_at(-2e-3, 0.0);
  const WheelForces f = wheel_forces(c, 1);
  WheelOutput a, b;
  set_force_outputs(f, f.normal_force, 1, a);
  set_force_outputs(f, f.normal_force + 1000.0, 1, b);
  EXPECT_NEAR(b.vertical_force - a.vertical_force, 1000.0 * f.normal_direction.z(), 1e-9);
  EXPECT_NEAR(b.lateral_force - a.lateral_force, 1000.0 * f.normal_direction.y(), 1e-9);  // right: +y
  EXPECT_NEAR(f.normal_direction.norm(), 1.0, 1e-12);  // one patch: a unit normal
  EXPECT_THROW(wheel_forces(c, 2), std::invalid_argument);
}

// Inside a spline transition the rigid wheel's multiplier N is shared over two patches, one per
// branch, each along its own normal: their normal forces add up, as vectors, to N along the
// blend's normal while sum_p N_p exceeds N. Given N, wheel_forces() keeps the direction a unit
// vector (to rounding) and force(N) is the patches' own sum; by default (sum_p N_p) it would not be.
TEST(WheelForces, ASplineTransitionsPatchesAddUpToTheMultiplier) {
  const auto geometry = test::s1002_uic60_geometry();
  const auto spline = make_contact_model("spline", geometry, ContactModelOptions{}, test::quick_spline_data());
  ContactQuery q;
  q.pose.z = 0.46;
  q.pose.roll = 0.0003;
  q.speed = 30.0;
  q.spin_rate = q.speed / 0.46;
  q.normal_load = {77e3, 77e3};
  int split = 0;
  for (int i = 0; i <= 60; ++i) {
    q.pose.y = 0.0045 + 2.5e-5 * i;
    const ContactResult c = spline->evaluate(q);
    if (std::count_if(c.patches.begin(), c.patches.end(), [](const ContactPatch& p) { return p.point.side == WheelSide::kLeft; }) != 2)
      continue;
    ++split;
    const WheelForces f = wheel_forces(c, 0, q.normal_load[0]);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const ContactPatch& p : c.patches)
      if (p.point.side == WheelSide::kLeft) sum += patch_forces(p).normal + patch_forces(p).creep;
    EXPECT_NEAR(f.normal_direction.norm(), 1.0, 1e-12) << "y " << q.pose.y;
    EXPECT_NEAR((f.force(q.normal_load[0]) - sum).norm(), 0.0, 1e-9 * q.normal_load[0]);
    EXPECT_GT(f.normal_force, q.normal_load[0] * (1.0 + 1e-9)) << "the split's magnitudes exceed N";
  }
  EXPECT_GT(split, 0) << "the sweep must cross a transition";
  EXPECT_THROW(wheel_forces(spline->evaluate(q), 0, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace wrc
