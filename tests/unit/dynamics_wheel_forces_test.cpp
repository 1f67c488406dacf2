// SPDX-License-Identifier: Apache-2.0
// Y, Q, the creep forces, T gamma and p_max of one wheel from the patches of one contact result of
// a real model (one-point, S1002 on UIC60, a displaced, yawed and moving wheelset so that every
// creepage is non-zero), against a computation written out here from the patch fields: the contact
// frame built by hand (t1 = e_x projected onto the contact plane, t2 = n x t1), the sums and signs of
// docs/run-quantities.md. And the physical signs: in flange contact the flanging wheel's Y and Y/Q
// are positive and large.
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

struct HandSums {
  double y = 0, q = 0, fx = 0, fy = 0, t_gamma = 0, p_max = 0, n = 0;
};

// The wheel's sums, written out from the patch fields.
HandSums by_hand(const ContactResult& c, int wheel) {
  HandSums h;
  const double side = wheel == 0 ? 1.0 : -1.0;  // left wheel at +y
  for (const ContactPatch& p : c.patches) {
    if (static_cast<int>(p.point.side) != wheel) continue;
    const Eigen::Vector3d n = p.point.normal.normalized();
    const Eigen::Vector3d ex(1.0, 0.0, 0.0);
    const Eigen::Vector3d t1 = (ex - ex.dot(n) * n).normalized();
    const Eigen::Vector3d t2 = n.cross(t1);
    const Eigen::Vector3d f = p.normal_force * n + p.forces.fx * t1 + p.forces.fy * t2;
    h.y += -side * f.y();  // towards the track centre
    h.q += f.z();
    h.fx += p.forces.fx;
    h.fy += p.forces.fy;
    h.t_gamma += std::abs(p.forces.fx * p.creepages.longitudinal) + std::abs(p.forces.fy * p.creepages.lateral);
    h.p_max = std::max(h.p_max, 3.0 * p.normal_force / (2.0 * kPi * p.a * p.b));
    h.n += p.normal_force;
  }
  return h;
}

// Every read-off of both wheels equals the hand computation to rounding (1e-12 relative: the same
// sums in another order), and both wheels' forces add up to the model's own resultant (its
// add_to_resultant), to 1e-9 of the load.
TEST(WheelForces, MatchAHandComputationFromThePatches) {
  for (const double y : {-2e-3, 3e-3}) {
    const ContactResult c = contact_at(y, 1.5e-3);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int wheel = 0; wheel < 2; ++wheel) {
      const HandSums h = by_hand(c, wheel);
      ASSERT_GT(h.n, 0.0);
      ASSERT_GT(h.t_gamma, 0.0) << "the state must have creepage for the test to mean something";
      const WheelForces f = wheel_forces(c, wheel);
      WheelOutput out;
      set_force_outputs(f, f.normal_force, wheel, out);
      const double scale = h.n;  // [N]
      EXPECT_NEAR(f.normal_force, h.n, 1e-12 * scale);
      EXPECT_NEAR(out.lateral_force, h.y, 1e-12 * scale) << "y " << y << " wheel " << wheel;
      EXPECT_NEAR(out.vertical_force, h.q, 1e-12 * scale);
      EXPECT_NEAR(out.creep_force_x, h.fx, 1e-12 * scale);
      EXPECT_NEAR(out.creep_force_y, h.fy, 1e-12 * scale);
      EXPECT_NEAR(out.wear_number, h.t_gamma, 1e-12 * h.t_gamma);
      EXPECT_NEAR(out.max_pressure, h.p_max, 1e-12 * h.p_max);
      EXPECT_NEAR(out.y_over_q(), h.y / h.q, 1e-12);
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
