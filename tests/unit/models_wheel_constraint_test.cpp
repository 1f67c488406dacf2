// SPDX-License-Identifier: Apache-2.0
// The contact constraint every model returns per wheel (WheelConstraint): the gap's gradient
// against central differences of the gap itself, the event function of the one-point branches at
// a real jump of S1002 on UIC60, and the branch rules on synthetic potential points.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/models/contact_model_factory.hpp"
#include "core/models/wheel_constraint.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

ContactQuery query_at(double y, double roll, double yaw, double z = 0.46) {
  ContactQuery q;
  q.pose.y = y;
  q.pose.roll = roll;
  q.pose.yaw = yaw;
  q.pose.z = z;
  q.spin_rate = q.speed / 0.46;
  q.normal_load = {80e3, 80e3};
  return q;
}

// d gap / d(y, z, roll, yaw) by central differences of the model's own gap (same branch).
Eigen::Vector4d numeric_gradient(const ContactModel& model, ContactQuery q, int wheel, double h) {
  const ContactResult base = model.evaluate(q);
  q.tracked_s_wheel = {base.wheels[0].s_wheel, base.wheels[1].s_wheel};
  Eigen::Vector4d g;
  for (int k = 0; k < 4; ++k) {
    ContactQuery plus = q, minus = q;
    double* coordinate[2][4] = {{&plus.pose.y, &plus.pose.z, &plus.pose.roll, &plus.pose.yaw},
                                {&minus.pose.y, &minus.pose.z, &minus.pose.roll, &minus.pose.yaw}};
    *coordinate[0][k] += h;
    *coordinate[1][k] -= h;
    g[k] = (model.evaluate(plus).wheels[static_cast<size_t>(wheel)].gap -
            model.evaluate(minus).wheels[static_cast<size_t>(wheel)].gap) /
           (2.0 * h);
  }
  return g;
}

// The envelope-theorem gradient of the exact geometry equals the derivative of the gap: to the
// truncation error of the difference (h^2 * third derivative ~ 1e-10) and the root tolerance.
TEST(WheelConstraint, OnePointGapGradientMatchesDifferences) {
  const auto model = make_contact_model("onepoint", test::s1002_uic60_geometry());
  for (const double y : {0.0, 2e-3, -3.5e-3, 4.5e-3}) {
    const ContactQuery q = query_at(y, 2e-4, 3e-3);
    const ContactResult r = model->evaluate(q);
    for (int wheel = 0; wheel < 2; ++wheel) {
      const Eigen::Vector4d numeric = numeric_gradient(*model, q, wheel, 1e-6);
      const Eigen::Vector4d& analytic = r.wheels[static_cast<size_t>(wheel)].gap_gradient;
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(analytic[k], numeric[k], 1e-6 * (1.0 + std::abs(numeric[k]))) << "y " << y << " wheel " << wheel
                                                                                  << " coordinate " << k;
      EXPECT_DOUBLE_EQ(analytic[1], 1.0);  // the gap is a vertical distance
    }
  }
}

// The spline model's gradient is that of its fitted z (exactly the derivative of its gap).
TEST(WheelConstraint, SplineGapGradientMatchesDifferences) {
  const auto model = make_contact_model("spline", test::s1002_uic60_geometry(), {},
                                        ContactModelData{test::quick_spline_fit().model});
  for (const double y : {0.0, 1e-3, 4.9e-3, -4.9e-3}) {
    const ContactQuery q = query_at(y, 1e-4, 1e-3);
    const ContactResult r = model->evaluate(q);
    for (int wheel = 0; wheel < 2; ++wheel) {
      if (r.wheels[static_cast<size_t>(wheel)].switch_function <= 0.0) continue;  // flange: exact
      const Eigen::Vector4d numeric = numeric_gradient(*model, q, wheel, 1e-7);
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(r.wheels[static_cast<size_t>(wheel)].gap_gradient[k], numeric[k], 1e-6 * (1.0 + std::abs(numeric[k])))
            << "y " << y << " wheel " << wheel << " coordinate " << k;
    }
  }
}

// Across the tread jump of the left wheel near y = 5 mm (S1002/UIC60, no roll or yaw, fixed
// height) the one-point model's event function, with the branch held, is continuous and changes
// sign where the common point (the untracked model's lowest point) jumps; past the root the
// untracked model is on the switch target.
TEST(WheelConstraint, OnePointEventFunctionChangesSignAtTheJump) {
  const auto model = make_contact_model("onepoint", test::s1002_uic60_geometry());
  ContactQuery q = query_at(4.8e-3, 0.0, 0.0);
  const ContactResult before = model->evaluate(q);
  q.tracked_s_wheel = {before.wheels[0].s_wheel, before.wheels[1].s_wheel};
  double previous = before.wheels[0].switch_function;
  ASSERT_GT(previous, 0.0);
  double root = std::numeric_limits<double>::quiet_NaN();
  double target = 0.0;
  for (double y = 4.8e-3; y < 5.3e-3; y += 1e-6) {
    q.pose.y = y;
    const ContactResult r = model->evaluate(q);
    const double g = r.wheels[0].switch_function;
    EXPECT_LT(std::abs(g - previous), 1e-6) << "the event function jumps at y = " << y;
    if (previous > 0.0 && g <= 0.0) {
      root = y;
      target = r.wheels[0].switch_s_wheel;
      break;
    }
    previous = g;
    q.tracked_s_wheel[0] = r.wheels[0].s_wheel;
  }
  ASSERT_FALSE(std::isnan(root)) << "no sign change of the event function between 4.8 and 5.3 mm";
  // Where the untracked common point arrives on the target branch, by bisection to 1e-9 m.
  double lo = 4.8e-3, hi = 5.3e-3;
  while (hi - lo > 1e-9) {
    const double mid = 0.5 * (lo + hi);
    (std::abs(model->evaluate(query_at(mid, 0.0, 0.0)).wheels[0].s_wheel - target) < 1e-3 ? hi : lo) = mid;
  }
  EXPECT_NEAR(root, hi, 1.5e-6);  // the scan's step
  const ContactResult lowest = model->evaluate(query_at(root + 2e-6, 0.0, 0.0));
  EXPECT_NEAR(lowest.wheels[0].s_wheel, target, 1e-4);
  EXPECT_GT(std::abs(target - before.wheels[0].s_wheel), 5e-3);  // a jump of the point on the wheel
}

ContactPoint point(double s, double distance, bool minimum) {
  ContactPoint p;
  p.s = s;
  p.distance = distance;
  p.is_minimum = minimum;
  return p;
}

TEST(WheelConstraint, BranchRules) {
  // Minima at s = -10, 5, 20 mm with maxima between, distances 3, 1, 2 um.
  const std::vector<ContactPoint> points{point(-0.010, 3e-6, true), point(-0.002, 9e-6, false),
                                         point(0.005, 1e-6, true), point(0.012, 4e-6, false),
                                         point(0.020, 2e-6, true)};
  const TrackedBranch lowest = track_branch(points, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(lowest.index, 2u);
  EXPECT_NEAR(lowest.switch_function, 1e-6, 1e-15);  // the next lowest minimum, 2 um
  EXPECT_DOUBLE_EQ(lowest.switch_s_wheel, 0.020);
  const TrackedBranch followed = track_branch(points, 0.0195);
  EXPECT_EQ(followed.index, 4u);
  EXPECT_NEAR(followed.switch_function, -1e-6, 1e-15);  // no longer the lowest: past its event
  EXPECT_DOUBLE_EQ(followed.switch_s_wheel, 0.005);
  // A followed minimum that merged with its maximum: the nearest minimum is far away.
  const TrackedBranch lost = track_branch(points, 0.0125 + kBranchLostDistance);
  EXPECT_LT(lost.switch_function, 0.0);
  EXPECT_DOUBLE_EQ(lost.switch_s_wheel, 0.005);
  // A single minimum next to a maximum: the fold is the event.
  const TrackedBranch fold = track_branch({point(0.0, 5e-6, true), point(0.001, 5.5e-6, false)}, 0.0);
  EXPECT_NEAR(fold.switch_function, 0.5e-6, 1e-15);
  EXPECT_THROW(track_branch({point(0.0, 1e-6, false)}, 0.0), std::invalid_argument);
}

// Rigid two-point contact: the pair is the two minima nearest to their tracked s; it is left for
// a third minimum that becomes lower than the pair, for the survivor where one of the pair merges
// with a maximum, and at once (negative) when one of them has vanished.
TEST(WheelConstraint, TwoPointBranchRules) {
  // Minima at -10, 5, 20 mm (distances 3, 1, 1.2 um) with maxima at -2 (9 um) and 12 mm (1.5 um).
  const std::vector<ContactPoint> points{point(-0.010, 3e-6, true), point(-0.002, 9e-6, false),
                                         point(0.005, 1e-6, true), point(0.012, 1.5e-6, false),
                                         point(0.020, 1.2e-6, true)};
  const TwoPointBranches pair = track_two_point(points, 0.0049, 0.0201);
  EXPECT_EQ(pair.first, 2u);
  EXPECT_EQ(pair.second, 4u);
  EXPECT_NEAR(pair.switch_function, 0.3e-6, 1e-15);  // the maximum between them, 0.3 um above the second
  EXPECT_DOUBLE_EQ(pair.switch_s_wheel, 0.005);       // where the second one merges with it: the first survives
  // A third minimum lower than the pair.
  std::vector<ContactPoint> lower = points;
  lower[0].distance = 0.4e-6;
  lower[3].distance = 9e-6;
  const TwoPointBranches left = track_two_point(lower, 0.0049, 0.0201);
  EXPECT_NEAR(left.switch_function, -0.6e-6, 1e-15);
  EXPECT_DOUBLE_EQ(left.switch_s_wheel, -0.010);
  // The second point has vanished (no minimum near its tracked s but the first one).
  const TwoPointBranches lost = track_two_point({point(0.0, 1e-6, true), point(0.004, 2e-6, false)}, 0.0, 0.006);
  EXPECT_LT(lost.switch_function, 0.0);
  EXPECT_EQ(lost.second, lost.first);
  EXPECT_DOUBLE_EQ(lost.switch_s_wheel, 0.0);
  EXPECT_THROW(track_two_point({point(0.0, 1e-6, false)}, 0.0, 0.01), std::invalid_argument);
}

// Every model returns both wheels whatever their load, and the interp and multipoint models
// declare no jumps.
TEST(WheelConstraint, BothWheelsAlwaysPresent) {
  ContactQuery q = query_at(1e-3, 0.0, 0.0);
  q.normal_load = {0.0, 0.0};
  for (const std::string name : {"onepoint", "interp", "multipoint"}) {
    const auto model = make_contact_model(name, test::s1002_uic60_geometry());
    const ContactResult r = model->evaluate(q);
    EXPECT_TRUE(r.patches.empty()) << name;
    for (const WheelConstraint& w : r.wheels) {
      EXPECT_GT(w.gap, 0.0) << name;  // z = 0.46 lies above the touching height
      EXPECT_GT(w.normal_z, 0.9) << name;
    }
    if (name != "onepoint") {
      EXPECT_EQ(r.wheels[0].switch_function, kNoSwitch) << name;
    }
  }
}

}  // namespace
}  // namespace wrc
