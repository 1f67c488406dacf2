// SPDX-License-Identifier: Apache-2.0
// Unit tests of the creepages from wheelset motion (services/core/contact/creepage.hpp), against the
// linearised table of docs/contact-mechanics.md, "Creepages", with the track frame x forward, y left, z up.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/contact/creepage.hpp"

namespace {

using Eigen::Vector3d;

constexpr double kV = 30.0;    // forward speed [m/s]
constexpr double kR0 = 0.46;   // nominal rolling radius [m]
constexpr double kA0 = 0.75;   // half distance of the contact points [m]

// Left wheel normal for contact angle delta: from the rail into the wheel, pushing to the track centre.
Vector3d left_normal(double delta) { return {0, -std::sin(delta), std::cos(delta)}; }
Vector3d right_normal(double delta) { return {0, std::sin(delta), std::cos(delta)}; }

// Verifies pure rolling of a centred wheelset with flat contact: omega = V/r0 about the axle, contact at
// r0 directly below the wheel: all three creepages vanish (to rounding, 1e-15).
TEST(CreepCreepages, PureRollingGivesZero) {
  const Vector3d omega(0, kV / kR0, 0);
  for (double side : {+1.0, -1.0}) {
    const auto c = wrc::creepages(kV, {kV, 0, 0}, omega, {0, side * kA0, -kR0}, {0, 0, 1});
    EXPECT_NEAR(c.longitudinal, 0.0, 1e-15);
    EXPECT_NEAR(c.lateral, 0.0, 1e-15);
    EXPECT_NEAR(c.spin, 0.0, 1e-15);
  }
}

// Verifies the spin row of the table for a centred wheelset with equal contact angles on both wheels:
// left phi_s = -sin(delta)/r0, right +sin(delta)/r0 (equal and opposite, so the spin-induced lateral
// forces cancel: zero net lateral force), and the longitudinal/lateral creepages vanish. Exact formulas,
// 1e-14 absolute on values of order 0.1 1/m.
TEST(CreepCreepages, CentredWheelsetHasEqualAndOppositeSpin) {
  const double delta = 0.05;
  const Vector3d omega(0, kV / kR0, 0);
  // With a tilted normal the contact point still lies at radius r0 below the axle (conical tread).
  const auto left = wrc::creepages(kV, {kV, 0, 0}, omega, {0, kA0, -kR0}, left_normal(delta));
  const auto right = wrc::creepages(kV, {kV, 0, 0}, omega, {0, -kA0, -kR0}, right_normal(delta));
  EXPECT_NEAR(left.spin, -std::sin(delta) / kR0, 1e-14);
  EXPECT_NEAR(right.spin, +std::sin(delta) / kR0, 1e-14);
  EXPECT_NEAR(left.spin + right.spin, 0.0, 1e-14);
  EXPECT_NEAR(left.lateral + right.lateral, 0.0, 1e-14);
  EXPECT_NEAR(left.longitudinal, 0.0, 1e-14);
  EXPECT_NEAR(right.longitudinal, 0.0, 1e-14);
}

// Verifies each row of the linearised table on both wheels for small perturbations: lateral shift
// (rolling radii r_L != r_R), yaw psi, yaw rate, lateral velocity, roll rate and spin perturbation beta'.
// The vector form is exact, the table is its first-order expansion, so their difference must be of second
// order: with all perturbations scaled by s, the difference at s = 0.1 must be below 2 % of the one at
// s = 1 (exact second order gives 1 %), while the creepages themselves scale with s (first order). At
// s = 1 (psi = 2 mrad, r - r0 = 5 mm, ...) the difference must stay below 5e-5, i.e. products such as
// psi (r - r0)/r0 = 2.2e-5. The inputs satisfy rigid contact (zero normal slip velocity), the condition
// under which the table's 1/cos(delta) holds. The spin row is checked with the exact spin
// Omega = V/r0 + beta' (the table writes V/r0), to 1e-12.
TEST(CreepCreepages, MatchesLinearisedTableOnBothWheels) {
  const double d_left = 0.04, d_right = 0.03;
  auto difference = [&](double s, double side, double* spin_error) {
    const double psi = 2e-3 * s, psi_dot = 0.05 * s, y_dot = 0.02 * s, phi_dot = 0.01 * s, beta_dot = 0.3 * s;
    const double r = kR0 + side * 5e-3 * s, d = side > 0 ? d_left : d_right;
    const Vector3d n = side > 0 ? left_normal(d) : right_normal(d);
    const double Omega = kV / kR0 + beta_dot;
    const Vector3d omega(phi_dot - psi * Omega, Omega, psi_dot);
    const Vector3d rc(-side * kA0 * psi, side * kA0, -r);
    Vector3d vg(kV, y_dot, 0);
    vg.z() = -(vg + omega.cross(rc)).dot(n) / n.z();  // rigid contact: no slip along n
    const auto c = wrc::creepages(kV, vg, omega, rc, n);
    const double xi_x = (kR0 - r) / kR0 - side * kA0 * psi_dot / kV - r * beta_dot / kV;
    const double xi_y = (y_dot + r * phi_dot - kV * psi) / (kV * std::cos(d));
    *spin_error = c.spin - (-side * std::sin(d) * Omega / kV + psi_dot * std::cos(d) / kV);
    EXPECT_GT(std::abs(xi_x), 1e-3 * s);  // the perturbations really are first order
    EXPECT_GT(std::abs(xi_y), 1e-3 * s);
    return std::max(std::abs(c.longitudinal - xi_x), std::abs(c.lateral - xi_y));
  };
  for (double side : {+1.0, -1.0}) {
    double spin_error = 0;
    const double big = difference(1.0, side, &spin_error);
    EXPECT_NEAR(spin_error, 0.0, 1e-12) << "side " << side;
    const double small = difference(0.1, side, &spin_error);
    EXPECT_NEAR(spin_error, 0.0, 1e-12) << "side " << side;
    EXPECT_LT(big, 5e-5) << "side " << side;
    EXPECT_LT(small, 0.02 * big) << "side " << side;
  }
}

// Verifies the signs of the lateral creepage under yaw alone: psi > 0 (wheelset turned counter-clockwise,
// heading to the left) makes the wheel material slide towards -y relative to its rolling direction, so
// xi_y = -psi (flat contact, exact in the vector form up to cos(psi) ~ 1 - 2e-6).
TEST(CreepCreepages, YawGivesNegativeLateralCreepage) {
  const double psi = 2e-3;
  const Vector3d omega(-psi * kV / kR0, kV / kR0, 0);
  const auto c = wrc::creepages(kV, {kV, 0, 0}, omega, {-kA0 * psi, kA0, -kR0}, {0, 0, 1});
  EXPECT_NEAR(c.lateral, -psi, 1e-8);
}

// Verifies the error contract: V <= 0, NaN inputs, a zero normal and a normal along x are rejected.
TEST(CreepCreepages, RejectsInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vector3d z(0, 0, 1), zero(0, 0, 0);
  EXPECT_THROW(wrc::creepages(0.0, zero, zero, zero, z), std::invalid_argument);
  EXPECT_THROW(wrc::creepages(kV, Vector3d(nan, 0, 0), zero, zero, z), std::invalid_argument);
  EXPECT_THROW(wrc::creepages(kV, zero, zero, zero, zero), std::invalid_argument);
  EXPECT_THROW(wrc::creepages(kV, zero, zero, zero, Vector3d(1, 0, 0)), std::invalid_argument);
  const auto f = wrc::contact_frame({0, -0.6, 0.8});
  EXPECT_NEAR(f.t1.dot(f.n), 0.0, 1e-15);
  EXPECT_NEAR(f.t2.dot(f.n), 0.0, 1e-15);
  EXPECT_NEAR(f.t1.cross(f.t2).dot(f.n), 1.0, 1e-15);  // right-handed
}

}  // namespace
