// The spline contact model ("spline") against the exact one-point model: the same patches away
// from the jumps of the common point, the exact geometry in flange contact, OutsideModelError
// outside its box, and a continuous contact point across a tread jump where one-point contact
// jumps.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/models/one_point_model.hpp"
#include "core/models/spline_model.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

using test::default_spline_fit;
using test::s1002_uic60_geometry;

ContactQuery rigid_query(double y, double roll, double yaw) {
  ContactQuery q;
  q.pose.y = y;
  q.pose.roll = roll;
  q.pose.yaw = yaw;
  q.pose.z = 0.46;
  q.speed = 30.0;
  q.spin_rate = 30.0 / 0.46;
  q.y_dot = 0.01;  // some lateral creepage, so that fy is not ~0
  q.normal_load = {77e3, 77e3};
  return q;
}

// Away from the jumps (>= 1 mm) the fitted contact point, ellipse and creep forces agree with
// the one-point model at the exact common point. Bounds are the model's targets (each branch is
// fitted on its own, so nothing of a jump reaches here): the contact angle to 0.5 mrad (measured
// 0.015 mrad), the point to 0.05 mm laterally (measured 2.2 um), the semi-axes to 2 % (measured
// 0.26 %: the rail's lateral curvature, R300 / R80 / R13, is constant on each branch) and the
// creep forces, which follow the semi-axes and the spin from the contact angle, to 1 % of mu N
// (measured 0.085 %).
TEST(SplineModel, AgreesWithOnePointAwayFromJumps) {
  const auto geometry = s1002_uic60_geometry();
  const SplineModel spline(geometry, default_spline_fit().model);
  const OnePointModel exact(geometry);
  double worst_angle = 0, worst_s = 0, worst_axis = 0, worst_force = 0;
  for (double y : {-0.0045, -0.0025, 0.0025, 0.0035}) {
    for (double yaw : {-0.002, 0.0}) {
      const ContactQuery q = rigid_query(y, 0.0, yaw);
      const ContactResult a = spline.evaluate(q), b = exact.evaluate(q);
      ASSERT_EQ(a.patches.size(), 2u);
      ASSERT_EQ(b.patches.size(), 2u);
      for (size_t k = 0; k < 2; ++k) {
        const ContactPatch &p = a.patches[k], &e = b.patches[k];
        worst_angle = std::max(worst_angle, std::abs(p.point.contact_angle - e.point.contact_angle));
        worst_s = std::max(worst_s, std::abs(p.point.s - e.point.s));
        worst_axis = std::max({worst_axis, std::abs(p.a / e.a - 1), std::abs(p.b / e.b - 1)});
        const double mu_n = 0.3 * e.normal_force;
        worst_force = std::max({worst_force, std::abs(p.forces.fx - e.forces.fx) / mu_n,
                                std::abs(p.forces.fy - e.forces.fy) / mu_n});
        EXPECT_DOUBLE_EQ(p.normal_force, e.normal_force);
      }
    }
  }
  std::cout << "worst: angle " << worst_angle << " rad, s " << worst_s << " m, semi-axes " << worst_axis
            << ", creep forces " << worst_force << " of mu N\n";
  EXPECT_LT(worst_angle, 5e-4);
  EXPECT_LT(worst_s, 5e-5);
  EXPECT_LT(worst_axis, 0.02);
  EXPECT_LT(worst_force, 0.01);
}

// Across the tread jump near y = 5.2 mm (left wheel) the one-point model's contact point jumps by
// ~11 mm while the spline model's moves continuously: over 20 steps of 0.05 mm no step of the
// spline point exceeds 3 mm (the blend over +-transition = 0.2 mm rises at most 15/8 / 0.4 mm:
// 1.875 x 11 mm x 0.05 / 0.4 = 2.6 mm), and the fitted clearance stays positive (no flange
// contact).
TEST(SplineModel, ContactPointIsContinuousAcrossATreadJump) {
  const auto geometry = s1002_uic60_geometry();
  const SplineModel spline(geometry, default_spline_fit().model);
  const OnePointModel exact(geometry);
  double spline_step = 0, exact_step = 0, last_spline = NAN, last_exact = NAN;
  for (int i = 0; i <= 20; ++i) {
    const ContactQuery q = rigid_query(0.0047 + 5e-5 * i, 0.0003, 0.0);
    const double s = spline.evaluate(q).patches[0].point.s, e = exact.evaluate(q).patches[0].point.s;
    if (i > 0) {
      spline_step = std::max(spline_step, std::abs(s - last_spline));
      exact_step = std::max(exact_step, std::abs(e - last_exact));
    }
    last_spline = s, last_exact = e;
  }
  std::cout << "largest step of s: spline " << spline_step << " m, one-point " << exact_step << " m\n";
  EXPECT_GT(exact_step, 0.008);
  EXPECT_LT(spline_step, 0.003);
}

// Outside its box the spline model answers nothing: OutsideModelError naming the coordinate,
// its value and the box (a configuration outside the model, not a derailment).
TEST(SplineModel, OutsideTheBoxIsAnOutsideModelError) {
  const SplineModel spline(s1002_uic60_geometry(), default_spline_fit().model);
  struct Case {
    double y, roll, yaw;
    const char* text;
  };
  for (const Case& c : {Case{0.0065, 0.0, 0.0, "y = 0.0065 m not in [-0.006, 0.006] m"},
                        Case{0.0, 0.0015, 0.0, "roll = 0.0015 rad not in [-0.001, 0.001] rad"},
                        Case{0.0, 0.0, -0.0055, "yaw = -0.0055 rad not in [-0.005, 0.005] rad"}}) {
    try {
      spline.evaluate(rigid_query(c.y, c.roll, c.yaw));
      ADD_FAILURE() << "no exception for " << c.text;
    } catch (const OutsideModelError& e) {
      EXPECT_NE(std::string(e.what()).find(c.text), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("wheel's configuration is outside the spline model's box"),
                std::string::npos)
          << e.what();
    }
  }
}

// Flange contact is physical and kept: with a box reaching into flange contact (|y| <= 7 mm; the
// left wheel touches its flange flank from ~6.5 mm at roll 0), the fitted flange clearance
// changes sign once along y, and where it is <= 0 the model returns the exact common point's
// patch, identical to the one-point model's.
TEST(SplineModel, FlangeContactUsesTheExactGeometry) {
  const auto geometry = s1002_uic60_geometry();
  SplineFitOptions o = test::quick_spline_options();
  o.y_min = -0.007;  // the right wheel's box is the mirror image: it must reach y = +7 mm too
  o.y_max = 0.007;
  const SplineFit fit = fit_spline_geometry(*geometry, o);
  ASSERT_GT(fit.wheels[0].samples_in_flange_contact, 0);
  const SplineModel spline(geometry, fit.model);
  const OnePointModel exact(geometry);
  int sign_changes = 0;
  double last = NAN;
  for (double y = 0.0055; y <= 0.00695; y += 1e-4) {
    WheelsetPose p;
    p.y = y, p.z = 0.46;
    SplineEvaluation e;
    fit.model->evaluate(WheelSide::kLeft, p, SplineDerivatives::kValue, e);
    const double clearance = e.value[kFieldFlangeClearance];
    if (!std::isnan(last) && (clearance > 0) != (last > 0)) ++sign_changes;
    last = clearance;
  }
  EXPECT_EQ(sign_changes, 1);
  EXPECT_LE(last, 0.0);
  const ContactQuery q = rigid_query(0.0069, 0.0, 0.0);
  const ContactResult a = spline.evaluate(q), b = exact.evaluate(q);
  ASSERT_EQ(a.patches.size(), 2u);
  EXPECT_DOUBLE_EQ(a.patches[0].point.s, b.patches[0].point.s);
  EXPECT_GT(a.patches[0].point.contact_angle, 0.8);  // on the flange flank
  EXPECT_DOUBLE_EQ(a.patches[0].a, b.patches[0].a);
  EXPECT_DOUBLE_EQ(a.patches[0].forces.fy, b.patches[0].forces.fy);
}

}  // namespace
}  // namespace wrc
