// SPDX-License-Identifier: Apache-2.0
// Hertzian one-point contact model (services/core/models/one_point_model.hpp): symmetry of a
// centred S1002/UIC60 wheelset, Kalker's linear theory as the small-creep limit and saturation at
// mu N through the whole model (geometry -> Hertz -> creepages -> FASTSIM), rigid/elastic
// consistency, and the resultant force and moment on the wheelset.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Eigen/Geometry>

#include "core/contact/hertz.hpp"
#include "core/contact/kalker_coefficients.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/one_point_model.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

constexpr double kLoad = 80e3;  // wheel load [N]
constexpr double kSpeed = 30.0; // [m/s]

std::shared_ptr<const WheelsetGeometry> s1002_uic60() {
  return std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                  make_profile("UIC60", ProfileSide::kRail));
}

// Cylindrical (cone slope 0) or conic wheel on a circular rail head of radius 0.3 m, no
// inclination, gauge at the top of rail 1.5 m: crown tops right below the taping lines.
std::shared_ptr<const WheelsetGeometry> cone_on_circle(const std::string& slope) {
  TrackParameters t;
  t.gauge = 1.5;
  t.gauge_depth = 0.0;
  t.inclination = 0.0;
  return std::make_shared<const WheelsetGeometry>(make_profile("conic:" + slope, ProfileSide::kWheel),
                                                  make_profile("circle:0.3", ProfileSide::kRail), t);
}

ContactQuery rigid_query(double y, double spin_rate) {
  ContactQuery q;
  q.pose.y = y;
  q.pose.z = 0.46;
  q.speed = kSpeed;
  q.spin_rate = spin_rate;
  q.normal_load = {kLoad, kLoad};
  q.formulation = ContactFormulation::kRigid;
  return q;
}

// Centred S1002/UIC60 wheelset rolling freely (spin = V / r at the contact points, no yaw, no
// rates): the mirror symmetry of the track must show in the result. Left and right spin are
// equal and opposite, longitudinal creepage vanishes, and the lateral forces cancel. The geometry
// of each wheel is computed separately (mirrored profiles), so the symmetry is only as exact as the
// floating-point evaluation: 1e-12 relative on creepages, 1e-9 of the load on the net forces.
TEST(ModelsOnePoint, CentredWheelsetIsSymmetric) {
  OnePointModel model(s1002_uic60());
  const double r = model.geometry().common_point(WheelSide::kLeft, WheelsetPose{0, 0.46, 0, 0, 0})->rolling_radius;
  for (ContactFormulation formulation : {ContactFormulation::kRigid, ContactFormulation::kElastic}) {
    ContactQuery q = rigid_query(0.0, kSpeed / r);
    q.formulation = formulation;
    if (formulation == ContactFormulation::kElastic) {
      // Lower the wheelset so that both common points overlap by 60 um vertically.
      const double d = model.geometry().common_point(WheelSide::kLeft, q.pose)->distance;
      q.pose.z -= d + 60e-6;
    }
    const ContactResult res = model.evaluate(q);
    ASSERT_EQ(res.patches.size(), 2u);
    const ContactPatch& left = res.patches[0];
    const ContactPatch& right = res.patches[1];
    EXPECT_EQ(left.point.side, WheelSide::kLeft);
    EXPECT_EQ(right.point.side, WheelSide::kRight);
    EXPECT_NEAR(left.normal_force, right.normal_force, 1e-9 * left.normal_force);
    EXPECT_GT(left.normal_force, 0.3 * kLoad);
    EXPECT_NEAR(left.creepages.longitudinal, 0.0, 1e-12);
    EXPECT_NEAR(right.creepages.longitudinal, 0.0, 1e-12);
    // Spin -sin(delta)/r0 on the left, +sin(delta)/r0 on the right (docs/contact-mechanics.md, "Creepages").
    EXPECT_LT(left.creepages.spin, 0.0);
    EXPECT_NEAR(left.creepages.spin, -right.creepages.spin, 1e-12 * std::fabs(left.creepages.spin));
    EXPECT_NEAR(left.creepages.spin, -std::sin(left.point.contact_angle) / r, 1e-3 * std::fabs(left.creepages.spin));
    EXPECT_NEAR(left.forces.fy, -right.forces.fy, 1e-9 * left.normal_force);
    EXPECT_NEAR(left.forces.mz, -right.forces.mz, 1e-9 * std::fabs(left.forces.mz) + 1e-12);
    EXPECT_NEAR(res.force.y(), 0.0, 1e-9 * left.normal_force);
    EXPECT_NEAR(res.moment.z(), 0.0, 1e-9 * left.normal_force);
    EXPECT_NEAR(res.moment.x(), 0.0, 1e-9 * left.normal_force);
  }
}

// Small yaw on a cylindrical wheel on a circular rail (contact angle 0, no spin): the lateral
// creepage is -r Omega sin(psi) / V and the lateral creep force must be Kalker's linear value
// -G c^2 C22 xi_y. FASTSIM's centre-value scheme reproduces the linear limit to +0.13 % at 20x20
// (contact_fastsim_test.cpp), so 0.5 % holds with margin and fails for any wrong a, b, c or C22.
TEST(ModelsOnePoint, SmallYawGivesLinearTheoryLateralForce) {
  OnePointModel model(cone_on_circle("0"));
  const double psi = 1e-4;
  ContactQuery q = rigid_query(0.0, kSpeed / 0.46);
  q.pose.yaw = psi;
  const ContactResult res = model.evaluate(q);
  ASSERT_EQ(res.patches.size(), 2u);
  for (const ContactPatch& p : res.patches) {
    EXPECT_NEAR(p.point.contact_angle, 0.0, 1e-12);
    const double xi_y = -p.point.rolling_radius * q.spin_rate * std::sin(psi) / kSpeed;
    EXPECT_NEAR(p.creepages.lateral, xi_y, 1e-9 * std::fabs(xi_y));
    EXPECT_NEAR(p.creepages.spin, 0.0, 1e-12);
    const KalkerCoefficients c = kalker_coefficients(p.a / p.b, q.material.poisson_ratio);
    const double linear = -q.material.shear_modulus * p.a * p.b * c.c22 * p.creepages.lateral;
    EXPECT_GT(p.forces.fy, 0.0);
    EXPECT_NEAR(p.forces.fy, linear, 5e-3 * std::fabs(linear));
  }
}

// Pure spin from conicity: a 1:40 cone on the circular rail, centred, no yaw, rolling at V / r.
// The creepages are xi_x = xi_y = 0 and phi_s = -+ sin(delta) / r (left / right), and the lateral
// force must be the linear theory's spin term -G c^3 C23 phi_s (its sign pushes each wheel towards
// the field side). FASTSIM 20x20 matched it within 0.4 % (3 % of the patch slides at this spin);
// tolerance 1 %. A wrong spin sign or frame flips the force.
TEST(ModelsOnePoint, ConicitySpinGivesLinearTheorySpinForce) {
  OnePointModel model(cone_on_circle("0.025"));
  const double r = model.geometry().common_point(WheelSide::kLeft, WheelsetPose{0, 0.46, 0, 0, 0})->rolling_radius;
  const ContactResult res = model.evaluate(rigid_query(0.0, kSpeed / r));
  ASSERT_EQ(res.patches.size(), 2u);
  for (const ContactPatch& p : res.patches) {
    const double sign = p.point.side == WheelSide::kLeft ? -1.0 : 1.0;
    EXPECT_NEAR(p.creepages.spin, sign * std::sin(std::atan(0.025)) / r, 1e-9);
    EXPECT_NEAR(p.creepages.lateral, 0.0, 1e-12);
    EXPECT_NEAR(p.creepages.longitudinal, 0.0, 1e-12);
    const KalkerCoefficients c = kalker_coefficients(p.a / p.b, 0.28);
    const double linear = -8.2e10 * std::pow(p.a * p.b, 1.5) * c.c23 * p.creepages.spin;
    EXPECT_NEAR(p.forces.fy, linear, 1e-2 * std::fabs(linear));
    EXPECT_EQ(p.forces.fy > 0, p.point.side == WheelSide::kLeft);
  }
}

// Large lateral creepage (y_dot / V = 0.1, fifty times the adhesion limit): the whole patch
// slides and the tangential force approaches mu N. FASTSIM's traction bound is charged at the
// element centres, and the midpoint sum of the concave parabolic bound over 20x20 elements
// exceeds its integral mu N slightly (+0.15 % measured), so |F| / (mu N) must lie within 1 % of 1.
TEST(ModelsOnePoint, LargeCreepageSaturatesAtMuN) {
  OnePointModel model(cone_on_circle("0"));
  ContactQuery q = rigid_query(0.0, kSpeed / 0.46);
  q.y_dot = 0.1 * kSpeed;
  const ContactResult res = model.evaluate(q);
  ASSERT_EQ(res.patches.size(), 2u);
  for (const ContactPatch& p : res.patches) {
    const double mu_n = q.material.friction * p.normal_force;
    const double f = std::hypot(p.forces.fx, p.forces.fy);
    EXPECT_NEAR(f / mu_n, 1.0, 1e-2);
    EXPECT_LT(p.forces.fy, 0.0);  // opposes the lateral slip of the wheel
    EXPECT_GT(p.forces.slip_fraction, 0.95);
  }
}

// Rigid and elastic formulations describe the same Hertz contact: the penetration that Hertz
// gives for the rigid load, applied as a vertical overlap delta / cos(angle) at the common point,
// must give back the load and the same ellipse in the elastic formulation (Hertz inverse, 1e-9).
// Checked on one wheel at an asymmetric position (y = 2 mm: 4.5 deg contact angle on the left).
TEST(ModelsOnePoint, ElasticForceAtRigidPenetrationReproducesLoad) {
  auto geometry = s1002_uic60();
  OnePointModel model(geometry);
  ContactQuery q = rigid_query(0.002, kSpeed / 0.46);
  const ContactResult rigid = model.evaluate(q);
  ASSERT_EQ(rigid.patches.size(), 2u);
  for (int w = 0; w < 2; ++w) {
    const ContactPatch& p = rigid.patches[static_cast<size_t>(w)];
    EXPECT_EQ(p.penetration, 0.0);
    const HertzShape shape = hertz_shape(p.point.relative_curvature_rolling(), p.point.relative_curvature_lateral());
    const double delta = hertz_from_force(shape, contact_modulus(q.material.shear_modulus, q.material.poisson_ratio),
                                          kLoad).penetration;
    ContactQuery e = q;
    e.formulation = ContactFormulation::kElastic;
    e.pose.z = q.pose.z - p.point.distance - delta / std::cos(p.point.contact_angle);
    const ContactResult elastic = model.evaluate(e);
    const ContactPatch* match = nullptr;
    for (const ContactPatch& ep : elastic.patches)
      if (ep.point.side == p.point.side) match = &ep;
    ASSERT_NE(match, nullptr);
    EXPECT_NEAR(match->penetration, delta, 1e-9 * delta);
    EXPECT_NEAR(match->normal_force, kLoad, 1e-9 * kLoad);
    EXPECT_NEAR(match->a, p.a, 1e-9 * p.a);
    EXPECT_NEAR(match->b, p.b, 1e-9 * p.b);
    EXPECT_NEAR(match->point.s, p.point.s, 1e-12);
  }
}

// Elastic formulation with the wheelset lifted: no overlap, no patch, zero resultant (not an error).
TEST(ModelsOnePoint, ElasticWithoutOverlapHasNoPatch) {
  OnePointModel model(s1002_uic60());
  ContactQuery q = rigid_query(0.0, kSpeed / 0.46);
  q.formulation = ContactFormulation::kElastic;
  q.pose.z = 0.47;  // 10 mm above touching
  const ContactResult res = model.evaluate(q);
  EXPECT_TRUE(res.patches.empty());
  EXPECT_EQ(res.force.norm(), 0.0);
  // A wheel with load 0 in the rigid formulation gets no patch either.
  ContactQuery r = rigid_query(0.0, kSpeed / 0.46);
  r.normal_load = {kLoad, 0.0};
  const ContactResult one = model.evaluate(r);
  ASSERT_EQ(one.patches.size(), 1u);
  EXPECT_EQ(one.patches[0].point.side, WheelSide::kLeft);
}

// The resultant is the sum of N n + fx t1 + fy t2 over the patches and its moment about the
// wheelset centre adds r x F and the spin moments mz n. Checked against an independent sum with
// the contact frame written out (t1 = x projected on the contact plane, t2 = n x t1), at an
// asymmetric, yawed and rolled configuration with all rates non-zero.
TEST(ModelsOnePoint, ResultantIsSumOfPatchForcesAndMoments) {
  OnePointModel model(s1002_uic60());
  ContactQuery q = rigid_query(0.003, kSpeed / 0.46 * 1.001);
  q.pose.roll = 0.002;
  q.pose.yaw = 0.003;
  q.pose.x = 12.0;
  q.y_dot = 0.05;
  q.z_dot = -0.01;
  q.roll_dot = 0.02;
  q.yaw_dot = -0.03;
  q.normal_load = {90e3, 70e3};
  const ContactResult res = model.evaluate(q);
  ASSERT_EQ(res.patches.size(), 2u);
  Eigen::Vector3d force(0, 0, 0), moment(0, 0, 0);
  const Eigen::Vector3d centre(q.pose.x, q.pose.y, q.pose.z);
  for (const ContactPatch& p : res.patches) {
    const Eigen::Vector3d n = p.point.normal.normalized();
    const Eigen::Vector3d t1 = (Eigen::Vector3d::UnitX() - n.x() * n).normalized();
    const Eigen::Vector3d t2 = n.cross(t1);
    const Eigen::Vector3d f = p.normal_force * n + p.forces.fx * t1 + p.forces.fy * t2;
    force += f;
    moment += (p.point.wheel_point - centre).cross(f) + p.forces.mz * n;
    // Lever arm: the contact points lie about 0.75 m sideways and r below the centre.
    EXPECT_NEAR(std::fabs(p.point.wheel_point.y() - centre.y()), 0.75, 0.02);
    EXPECT_NEAR(centre.z() - p.point.wheel_point.z(), p.point.rolling_radius, 0.01);
  }
  EXPECT_LT((res.force - force).norm(), 1e-9 * 160e3);
  EXPECT_LT((res.moment - moment).norm(), 1e-9 * 160e3);
}

}  // namespace
}  // namespace wrc
