// SPDX-License-Identifier: Apache-2.0
// Contact models at their boundary: malformed queries throw std::invalid_argument naming the field
// and the value (for every model), impossible configurations throw ContactConfigurationError, the
// factory knows its names, and the conformal-contact fallback for B <= 0 works as documented.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "core/contact/hertz.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

std::shared_ptr<const WheelsetGeometry> s1002_uic60() { return test::s1002_uic60_geometry(); }

ContactQuery good_query() {
  ContactQuery q;
  q.pose.z = 0.46;
  q.spin_rate = 30.0 / 0.46;
  q.normal_load = {80e3, 80e3};
  return q;
}

// Expects std::invalid_argument whose message contains `expected` (field, value and rule in one
// piece of text).
void expect_invalid(const ContactModel& model, const ContactQuery& q, const std::string& expected) {
  try {
    model.evaluate(q);
    ADD_FAILURE() << model.name() << ": no exception, expected '" << expected << "'";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(expected), std::string::npos) << model.name() << ": " << what;
  }
}

// Every malformed field is rejected before any computation, by every model, with the field's name
// and its value in the message.
TEST(ModelsValidation, BadQueriesThrowNamingTheField) {
  auto geometry = s1002_uic60();
  for (const std::string& name : contact_model_names()) {
    const auto model = make_contact_model(name, geometry, test::small_table_options(), test::quick_spline_data());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case {
      std::function<void(ContactQuery&)> spoil;
      std::string expected;  // field [unit] = value rule
    };
    // The library's message is "contact query: <field> [unit] = <value> <rule>"; each case matches
    // the field with its unit, the value and the rule with its bounds, so a "0" or "1" elsewhere
    // in the message cannot pass for the value.
    const Case cases[] = {
        {[&](ContactQuery& q) { q.pose.y = nan; }, "pose.y [m] = nan must be finite"},
        {[&](ContactQuery& q) { q.pose.roll = nan; }, "pose.roll [rad] = nan must be finite"},
        {[&](ContactQuery& q) { q.pose.yaw = 0.07; },  // beyond the validated 0.06
         "pose.yaw [rad] = 0.07 is beyond the validated range +-0.06 rad"},
        {[&](ContactQuery& q) { q.pose.z = std::numeric_limits<double>::infinity(); }, "pose.z [m] = inf must be finite"},
        {[&](ContactQuery& q) { q.yaw_dot = nan; }, "yaw_dot [rad/s] = nan must be finite"},
        {[&](ContactQuery& q) { q.spin_rate = nan; }, "spin_rate [rad/s] = nan must be finite"},
        {[](ContactQuery& q) { q.speed = 0.0; }, "speed [m/s] = 0 must be in (0, 1000]"},
        {[](ContactQuery& q) { q.speed = -5.0; }, "speed [m/s] = -5 must be in (0, 1000]"},
        {[](ContactQuery& q) { q.normal_load[1] = -10.0; },
         "normal_load[1] (right) [N] = -10 must be non-negative and finite"},
        {[&](ContactQuery& q) { q.normal_load[0] = nan; }, "normal_load[0] (left) [N] = nan must be non-negative"},
        {[](ContactQuery& q) { q.material.shear_modulus = 0.0; },
         "material.shear_modulus [Pa] = 0 must be in (0, 1e+13]"},
        {[](ContactQuery& q) { q.material.poisson_ratio = 0.5; },
         "material.poisson_ratio [-] = 0.5 must be in (0, 0.5)"},
        {[](ContactQuery& q) { q.material.poisson_ratio = 0.0; },
         "material.poisson_ratio [-] = 0 must be in (0, 0.5)"},
        {[](ContactQuery& q) { q.material.friction = -0.1; }, "material.friction [-] = -0.1 must be in [0, 10]"},
        {[](ContactQuery& q) { q.fastsim_elements = 1; }, "fastsim_elements = 1 must be in 2..400"},
        {[](ContactQuery& q) { q.fastsim_strips = 401; }, "fastsim_strips = 401 must be in 2..400"},
    };
    for (const Case& c : cases) {
      ContactQuery q = good_query();
      c.spoil(q);
      expect_invalid(*model, q, c.expected);
    }
    // The unspoilt query works, also with a non-default FASTSIM grid (cached solver).
    EXPECT_EQ(model->evaluate(good_query()).patches.size() >= 2, true) << name;
    ContactQuery fine = good_query();
    fine.fastsim_elements = 40;
    fine.fastsim_strips = 10;
    EXPECT_GE(model->evaluate(fine).patches.size(), 2u) << name;
  }
}

// A wheelset shifted 50 mm sideways has a wheel off its rail: ContactConfigurationError naming the
// wheel and y (interp and spline: the configuration lies outside the table or box, an
// OutsideModelError, also naming it), never a result.
TEST(ModelsValidation, WheelOffTheRailIsAConfigurationError) {
  auto geometry = s1002_uic60();
  for (const std::string& name : contact_model_names()) {
    const auto model = make_contact_model(name, geometry, test::small_table_options(), test::quick_spline_data());
    for (ContactFormulation formulation : {ContactFormulation::kRigid, ContactFormulation::kElastic}) {
      ContactQuery q = good_query();
      q.pose.y = 0.05;
      q.formulation = formulation;
      try {
        model->evaluate(q);
        ADD_FAILURE() << name << ": no exception at y = 0.05 m";
      } catch (const ContactConfigurationError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("0.05"), std::string::npos) << what;
        if (name != "interp") {
          EXPECT_NE(what.find("left wheel"), std::string::npos) << what;
        }
        const bool outside = dynamic_cast<const OutsideModelError*>(&e) != nullptr;
        EXPECT_EQ(outside, name == "interp" || name == "spline") << name << ": " << what;
      }
    }
  }
}

// The registry builds the four models under their names, says that "spline" needs its fitted
// splines and lists the known names for anything else.
TEST(ModelsValidation, FactoryNames) {
  auto geometry = s1002_uic60();
  EXPECT_EQ(contact_model_names(), (std::vector<std::string>{"onepoint", "interp", "multipoint", "spline"}));
  for (const std::string& name : contact_model_names()) {
    EXPECT_EQ(make_contact_model(name, geometry, test::small_table_options(), test::quick_spline_data())->name(), name);
    EXPECT_EQ(contact_model_entry(name).needs_data, name == "spline");
  }
  try {
    make_contact_model("spline", geometry);
    ADD_FAILURE() << "spline built";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("needs a fitted spline model"), std::string::npos) << e.what();
  }
  try {
    make_contact_model("twopoint", geometry);
    ADD_FAILURE() << "twopoint built";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("twopoint"), std::string::npos) << what;
    EXPECT_NE(what.find("onepoint, interp, multipoint, spline"), std::string::npos) << what;
  }
  EXPECT_THROW(make_contact_model("onepoint", nullptr), std::invalid_argument);
  ContactModelOptions bad;
  bad.interp.y_points = 1;
  EXPECT_THROW(make_contact_model("interp", geometry, bad), std::invalid_argument);
  bad = ContactModelOptions{};
  bad.lateral_curvature_floor = -1;
  EXPECT_THROW(make_contact_model("onepoint", geometry, bad), std::invalid_argument);
  bad = ContactModelOptions{};
  bad.interp.yaw_max = 0.08;  // beyond kMaxValidatedYaw
  try {
    make_contact_model("interp", geometry, bad);
    ADD_FAILURE() << "interp built with yaw_max = 0.08 rad";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("yaw_max = 0.08"), std::string::npos) << e.what();
  }
}

// Conformal contact (concave wheel profile flatter than the rail: B <= 0) has no Hertz ellipse.
// With the default floor, B is raised to 0.01 A and the patch is flagged; with the floor disabled
// the point is a ContactConfigurationError naming B.
TEST(ModelsValidation, ConformalCurvatureFloorAndError) {
  ContactPoint p;
  p.side = WheelSide::kLeft;
  p.s = -0.03;
  p.wheel_curvature_rolling = 1.0 / 0.47;
  p.wheel_curvature_lateral = -1.0 / 0.012;  // flange root fillet, concave
  p.rail_curvature_lateral = 1.0 / 0.013;    // gauge corner R13, convex but flatter
  ASSERT_LE(p.relative_curvature_lateral(), 0.0);
  const PatchShape floored = contact_shape(p, 0.01);
  EXPECT_TRUE(floored.floored);
  EXPECT_DOUBLE_EQ(floored.shape.A, p.relative_curvature_rolling());
  EXPECT_DOUBLE_EQ(floored.shape.B, 0.01 * p.relative_curvature_rolling());
  EXPECT_LT(floored.shape.axis_ratio, 1.0 / 10);  // wide patch, a/b ~ 1/16
  EXPECT_GT(floored.shape.axis_ratio, 1.0 / 50);
  try {
    contact_shape(p, 0.0);
    ADD_FAILURE() << "no exception with the floor disabled";
  } catch (const ContactConfigurationError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("B = "), std::string::npos) << what;
    EXPECT_NE(what.find("left wheel"), std::string::npos) << what;
  }
  // A regular point is left alone.
  p.rail_curvature_lateral = 1.0 / 0.3;
  p.wheel_curvature_lateral = 0.0;
  const PatchShape regular = contact_shape(p, 0.01);
  EXPECT_FALSE(regular.floored);
  EXPECT_DOUBLE_EQ(regular.shape.B, p.relative_curvature_lateral());
}

// The floor acts inside the models: a floor of 100 A lies above every S1002/UIC60 tread B, so
// every patch is flagged and its ellipse is the Hertz ellipse of (A, 100 A). The spline model's
// Hertz shapes are fitted with the floor of its fit, so it refuses another floor, naming both.
TEST(ModelsValidation, FloorIsAppliedInTheModels) {
  ContactModelOptions options = test::small_table_options();
  options.lateral_curvature_floor = 100.0;
  auto geometry = s1002_uic60();
  try {
    make_contact_model("spline", geometry, options, test::quick_spline_data());
    ADD_FAILURE() << "spline built with another floor";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lateral_curvature_floor = 100"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.01"), std::string::npos) << e.what();
  }
  for (const std::string& name : contact_model_names()) {
    if (name == "spline") continue;
    const ContactResult res = make_contact_model(name, geometry, options)->evaluate(good_query());
    ASSERT_FALSE(res.patches.empty());
    for (const ContactPatch& p : res.patches) {
      EXPECT_TRUE(p.lateral_curvature_floored) << name;
      const double A = p.point.relative_curvature_rolling();
      const HertzContact h = hertz_from_force(A, 100 * A, contact_modulus(8.2e10, 0.28), p.normal_force);
      EXPECT_NEAR(p.a, h.a, 1e-12) << name;
      EXPECT_NEAR(p.b, h.b, 1e-12) << name;
    }
  }
}

}  // namespace
}  // namespace wrc
