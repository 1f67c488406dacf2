// SPDX-License-Identifier: Apache-2.0
/// @file
/// The contact service's message adapter in-process (services/protocol/contact/contact_query_codec.hpp):
/// every message field lands in its own library field (all values distinct, so a swap shows),
/// every result field lands in its own message field, each invalid field is named with its value
/// and bounds, the adapter and the library accept and reject the same values of every field (the
/// library's rule, which the adapter applies),
/// and evaluate_query gives each configuration its status (stub model for every exception kind,
/// the real onepoint and interp models for IMPOSSIBLE_CONFIGURATION and OUTSIDE_MODEL), the
/// overall status being the worst one with that configuration's message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "contactd/query_evaluation.hpp"
#include "core/dynamics/contact_evaluator.hpp"
#include "core/model_interface/no_contact_error.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "protocol/contact/contact_query_codec.hpp"
#include "protocol/contact/contact_status.hpp"

namespace wrc::protocol {
namespace {

// A valid two-configuration query in which no two numeric fields share a value.
wrc::contact_query_t distinct_query() {
  wrc::contact_query_t q{};
  q.model = "onepoint";
  q.formulation = wrc::contact_query_t::ELASTIC;
  q.shear_modulus = 8.1e10;
  q.poisson_ratio = 0.27;
  q.friction = 0.33;
  q.fastsim_elements = 23;
  q.fastsim_strips = 17;
  q.num_configurations = 2;
  for (int i = 0; i < 2; ++i) {
    wrc::wheelset_configuration_t c{};
    const double k = i + 1.0;  // configuration 1 differs from configuration 0 in every field
    c.y = 0.0011 * k;
    c.z = 0.4601 * k;
    c.roll = 0.00021 * k;
    c.yaw = 0.0013 * k;
    c.y_dot = 0.017 * k;
    c.z_dot = -0.019 * k;
    c.roll_dot = 0.023 * k;
    c.yaw_dot = -0.029 * k;
    c.spin_rate = 68.3 * k;
    c.speed = 31.5 * k;
    c.normal_load_left = 71000.0 * k;
    c.normal_load_right = 69000.0 * k;
    q.configurations.push_back(c);
  }
  return q;
}

TEST(QueryAdapter, EveryMessageFieldLandsInItsLibraryField) {
  const wrc::contact_query_t q = distinct_query();
  ASSERT_EQ(validate_query(q), "");
  for (int i = 0; i < 2; ++i) {
    const double k = i + 1.0;
    const ContactQuery l = to_contact_query(q, i);
    EXPECT_EQ(l.pose.y, 0.0011 * k);
    EXPECT_EQ(l.pose.z, 0.4601 * k);
    EXPECT_EQ(l.pose.roll, 0.00021 * k);
    EXPECT_EQ(l.pose.yaw, 0.0013 * k);
    EXPECT_EQ(l.y_dot, 0.017 * k);
    EXPECT_EQ(l.z_dot, -0.019 * k);
    EXPECT_EQ(l.roll_dot, 0.023 * k);
    EXPECT_EQ(l.yaw_dot, -0.029 * k);
    EXPECT_EQ(l.spin_rate, 68.3 * k);
    EXPECT_EQ(l.normal_load[0], 71000.0 * k);
    EXPECT_EQ(l.normal_load[1], 69000.0 * k);
    EXPECT_EQ(l.speed, 31.5 * k);
    EXPECT_EQ(l.formulation, ContactFormulation::kElastic);
    EXPECT_EQ(l.material.shear_modulus, 8.1e10);
    EXPECT_EQ(l.material.poisson_ratio, 0.27);
    EXPECT_EQ(l.material.friction, 0.33);
    EXPECT_EQ(l.fastsim_elements, 23);
    EXPECT_EQ(l.fastsim_strips, 17);
  }
  wrc::contact_query_t rigid = q;
  rigid.formulation = wrc::contact_query_t::RIGID;
  EXPECT_EQ(to_contact_query(rigid, 0).formulation, ContactFormulation::kRigid);
}

TEST(QueryAdapter, EveryResultFieldLandsInItsMessageField) {
  ContactResult r;
  for (int i = 0; i < 2; ++i) {
    ContactPatch p;
    const double k = i + 1.0;
    p.point.side = i == 0 ? WheelSide::kLeft : WheelSide::kRight;
    p.point.s = 0.001 * k;
    p.point.s_rail = 0.002 * k;
    p.point.wheel_point = {0.003 * k, 0.004 * k, 0.005 * k};
    p.point.rail_point = {0.006 * k, 0.007 * k, 0.008 * k};
    p.point.normal = {0.009 * k, 0.010 * k, 0.011 * k};
    p.point.contact_angle = 0.012 * k;
    p.point.rolling_radius = 0.013 * k;
    p.a = 0.014 * k;
    p.b = 0.015 * k;
    p.penetration = 0.016 * k;
    p.normal_force = 0.017 * k;
    p.creepages = {0.018 * k, 0.019 * k, 0.020 * k};
    p.forces.fx = 0.021 * k;
    p.forces.fy = 0.022 * k;
    p.forces.mz = 0.023 * k;
    p.lateral_curvature_floored = i == 1;
    r.patches.push_back(p);
  }
  r.force = {0.024, 0.025, 0.026};
  r.moment = {0.027, 0.028, 0.029};
  wrc::contact_result_t m{};
  m.status = wrc::contact_reply_t::INTERNAL_ERROR;  // must be overwritten
  to_result_message(r, m);
  EXPECT_EQ(m.status, wrc::contact_reply_t::OK);
  ASSERT_EQ(m.num_patches, 2);
  ASSERT_EQ(m.patches.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    const double k = i + 1.0;
    const wrc::contact_patch_t& p = m.patches[static_cast<std::size_t>(i)];
    EXPECT_EQ(p.wheel, i == 0 ? wrc::contact_patch_t::LEFT : wrc::contact_patch_t::RIGHT);
    EXPECT_EQ(p.s_wheel, 0.001 * k);
    EXPECT_EQ(p.s_rail, 0.002 * k);
    for (int j = 0; j < 3; ++j) {
      EXPECT_DOUBLE_EQ(p.wheel_point[j], (0.003 + 0.001 * j) * k);
      EXPECT_DOUBLE_EQ(p.rail_point[j], (0.006 + 0.001 * j) * k);
      EXPECT_DOUBLE_EQ(p.normal[j], (0.009 + 0.001 * j) * k);
    }
    EXPECT_EQ(p.contact_angle, 0.012 * k);
    EXPECT_EQ(p.rolling_radius, 0.013 * k);
    EXPECT_EQ(p.a, 0.014 * k);
    EXPECT_EQ(p.b, 0.015 * k);
    EXPECT_EQ(p.penetration, 0.016 * k);
    EXPECT_EQ(p.normal_force, 0.017 * k);
    EXPECT_EQ(p.creepage_x, 0.018 * k);
    EXPECT_EQ(p.creepage_y, 0.019 * k);
    EXPECT_EQ(p.spin_creepage, 0.020 * k);
    EXPECT_EQ(p.fx, 0.021 * k);
    EXPECT_EQ(p.fy, 0.022 * k);
    EXPECT_EQ(p.mz, 0.023 * k);
    EXPECT_EQ(p.lateral_curvature_floored, i == 1 ? 1 : 0);
    EXPECT_EQ(from_result_message(m).patches[static_cast<std::size_t>(i)].lateral_curvature_floored, i == 1);
  }
  for (int j = 0; j < 3; ++j) {  // DOUBLE_EQ: 0.024 + 0.001 j is not exactly the literal; values differ by 1e-3
    EXPECT_DOUBLE_EQ(m.force[j], 0.024 + 0.001 * j);
    EXPECT_DOUBLE_EQ(m.moment[j], 0.027 + 0.001 * j);
  }
}

// Each invalid field is named with its value (and, for a range, the bounds in its unit).
TEST(QueryAdapter, EachInvalidFieldIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    std::function<void(wrc::contact_query_t&)> spoil;
    std::string expected;
  };
  const Case cases[] = {
      {[](auto& q) { q.formulation = 3; }, "formulation = 3 is neither RIGID (0) nor ELASTIC (1)"},
      {[](auto& q) { q.shear_modulus = 0.0; }, "shear_modulus = 0 is not positive"},
      {[](auto& q) { q.shear_modulus = 2e13; }, "shear_modulus = 2e+13 is outside (0, 1e+13] Pa"},
      {[](auto& q) { q.poisson_ratio = 0.5; }, "poisson_ratio = 0.5 is outside (0, 0.5) [-]"},
      {[](auto& q) { q.poisson_ratio = 0.0; }, "poisson_ratio = 0 is outside (0, 0.5) [-]"},
      {[&](auto& q) { q.poisson_ratio = nan; }, "poisson_ratio = nan is not a finite number"},
      {[](auto& q) { q.friction = -0.1; }, "friction = -0.1 is outside [0, 10] [-]"},
      {[](auto& q) { q.configurations[0].speed = 0.0; }, "configurations[0].speed = 0 is not positive"},
      {[](auto& q) { q.configurations[1].speed = 1500.0; }, "configurations[1].speed = 1500 is outside (0, 1000] m/s"},
      {[](auto& q) { q.fastsim_elements = 1; }, "fastsim_elements = 1 is outside [2, 400]"},
      {[](auto& q) { q.fastsim_strips = 401; }, "fastsim_strips = 401 is outside [2, 400]"},
      {[](auto& q) { q.num_configurations = 0; }, "num_configurations = 0 is outside [1, 32]"},
      {[](auto& q) { q.num_configurations = 3; }, "num_configurations = 3 but 2 configurations"},
      {[&](auto& q) { q.configurations[0].y = nan; }, "configurations[0].y = nan is not a finite number"},
      {[](auto& q) { q.configurations[1].z = 11.0; }, "configurations[1].z = 11 is outside [-10, 10] m"},
      {[](auto& q) { q.configurations[0].roll = 0.6; }, "configurations[0].roll = 0.6 is outside [-0.5, 0.5] rad"},
      {[](auto& q) { q.configurations[1].yaw = 0.07; }, "configurations[1].yaw = 0.07 is outside [-0.06, 0.06] rad"},
      {[](auto& q) { q.configurations[0].y_dot = 101.0; }, "configurations[0].y_dot = 101 is outside"},
      {[](auto& q) { q.configurations[0].z_dot = -101.0; }, "configurations[0].z_dot = -101 is outside"},
      {[](auto& q) { q.configurations[1].roll_dot = 102.0; }, "configurations[1].roll_dot = 102 is outside"},
      {[](auto& q) { q.configurations[1].yaw_dot = -103.0; }, "configurations[1].yaw_dot = -103 is outside"},
      {[](auto& q) { q.configurations[0].spin_rate = 2e4; }, "configurations[0].spin_rate = 20000 is outside"},
  };
  for (const Case& c : cases) {
    wrc::contact_query_t q = distinct_query();
    c.spoil(q);
    EXPECT_NE(validate_query(q).find(c.expected), std::string::npos)
        << "got '" << validate_query(q) << "', expected '" << c.expected << "'";
  }
  // Negative loads are errors in both formulations: the library's rule (validate_contact_query),
  // which the adapter applies; elastic models ignore the loads, but a bad one is still an error.
  for (const std::int8_t formulation : {wrc::contact_query_t::RIGID, wrc::contact_query_t::ELASTIC}) {
    wrc::contact_query_t q = distinct_query();
    q.formulation = formulation;
    q.configurations[1].normal_load_right = -5.0;
    EXPECT_NE(validate_query(q).find("configurations[1].normal_load_right = -5 is outside [0, 100000000] N"),
              std::string::npos)
        << validate_query(q);
    EXPECT_THROW(validate_contact_query(to_contact_query(q, 1)), std::invalid_argument);
  }
}

// Whether the library (validate_contact_query) accepts configuration index of q.
bool library_accepts(const wrc::contact_query_t& q, int index) {
  try {
    validate_contact_query(to_contact_query(q, index));
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

// The adapter and the library (validate_contact_query) accept and reject the same material and
// grid values: both take their bounds from core/model_interface/query_validation.hpp.
TEST(QueryAdapter, AcceptsWhatTheLibraryAccepts) {
  struct Probe {
    const char* what;
    std::function<void(wrc::contact_query_t&, double)> set;
    double values[6];
  };
  const Probe probes[] = {
      {"poisson_ratio", [](auto& q, double v) { q.poisson_ratio = v; }, {-0.01, 0.0, 1e-9, 0.25, 0.5 - 1e-12, 0.5}},
      {"shear_modulus", [](auto& q, double v) { q.shear_modulus = v; }, {-1.0, 0.0, 1.0, 8.2e10, 1e13, 1.0001e13}},
      {"friction", [](auto& q, double v) { q.friction = v; }, {-1e-9, 0.0, 0.3, 10.0, 10.0 + 1e-9, 20.0}},
      {"fastsim_elements", [](auto& q, double v) { q.fastsim_elements = static_cast<std::int32_t>(v); }, {0, 1, 2, 20, 400, 401}},
      {"fastsim_strips", [](auto& q, double v) { q.fastsim_strips = static_cast<std::int32_t>(v); }, {0, 1, 2, 20, 400, 401}},
  };
  for (const Probe& p : probes) {
    for (double v : p.values) {
      wrc::contact_query_t q = distinct_query();
      p.set(q, v);
      const bool adapter_accepts = validate_query(q).empty();
      EXPECT_EQ(adapter_accepts, library_accepts(q, 0)) << p.what << " = " << v << ": adapter '" << validate_query(q) << "'";
    }
  }
}

// The same for every configuration field, in both formulations: the adapter applies the library's
// rule to the converted configuration, so the two agree at and around every bound.
TEST(QueryAdapter, AcceptsTheConfigurationsTheLibraryAccepts) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  using Config = wrc::wheelset_configuration_t;
  struct Probe {
    const char* what;
    double Config::*field;
    double values[7];
  };
  const Probe probes[] = {
      {"y", &Config::y, {nan, -0.5000001, -0.5, 0.0, 0.5, 0.5000001, inf}},
      {"z", &Config::z, {nan, -10.000001, -10.0, 0.46, 10.0, 10.000001, -inf}},
      {"roll", &Config::roll, {nan, -0.5000001, -0.5, 0.0, 0.5, 0.5000001, inf}},
      {"yaw", &Config::yaw, {nan, -0.0600001, -0.06, 0.0, 0.06, 0.0600001, inf}},
      {"y_dot", &Config::y_dot, {nan, -100.0001, -100.0, 0.0, 100.0, 100.0001, inf}},
      {"roll_dot", &Config::roll_dot, {nan, -100.0001, -100.0, 0.0, 100.0, 100.0001, inf}},
      {"spin_rate", &Config::spin_rate, {nan, -10000.01, -1e4, 65.0, 1e4, 10000.01, inf}},
      {"speed", &Config::speed, {nan, -1.0, 0.0, 1e-6, 30.0, 1000.0, 1000.001}},
      {"normal_load_left", &Config::normal_load_left, {nan, -1e-9, 0.0, 8e4, 1e8, 1.0000001e8, inf}},
      {"second_normal_load_right", &Config::second_normal_load_right, {nan, -1e-9, 0.0, 8e4, 1e8, 1.0000001e8, inf}},
      {"tracked_s_wheel_right", &Config::tracked_s_wheel_right, {nan, -1.0000001, -1.0, -0.02, 1.0, 1.0000001, -inf}},
      {"second_tracked_s_wheel_left", &Config::second_tracked_s_wheel_left, {nan, -1.0000001, -1.0, 0.01, 1.0, 1.0000001, inf}},
  };
  for (const std::int8_t formulation : {wrc::contact_query_t::RIGID, wrc::contact_query_t::ELASTIC}) {
    for (const Probe& p : probes) {
      for (double v : p.values) {
        wrc::contact_query_t q = distinct_query();
        q.formulation = formulation;
        q.configurations[1].*p.field = v;
        const bool adapter_accepts = validate_query(q).empty();
        EXPECT_EQ(adapter_accepts, library_accepts(q, 1))
            << p.what << " = " << v << " (formulation " << int{formulation} << "): adapter '" << validate_query(q) << "'";
        if (!adapter_accepts) {
          EXPECT_NE(validate_query(q).find(std::string("configurations[1].") + p.what), std::string::npos)
              << validate_query(q);
        }
      }
    }
  }
}

// A model that throws what it is told to for configurations with y > 0 and answers y <= 0.
class StubModel : public ContactModel {
 public:
  StubModel(std::shared_ptr<const WheelsetGeometry> geometry, std::function<void()> fail)
      : geometry_(std::move(geometry)), fail_(std::move(fail)) {}
  std::string name() const override { return "stub"; }
  ContactResult evaluate(const ContactQuery& q) const override {
    if (q.pose.y > 0) fail_();
    ContactResult r;
    r.patches.resize(2);
    r.patches[1].point.side = WheelSide::kRight;
    return r;
  }
  const WheelsetGeometry& geometry() const override { return *geometry_; }

 private:
  std::shared_ptr<const WheelsetGeometry> geometry_;
  std::function<void()> fail_;
};

std::shared_ptr<const WheelsetGeometry> s1002_uic60() {
  static const auto geometry = std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                                        make_profile("UIC60", ProfileSide::kRail));
  return geometry;
}

// Configuration 0 (y < 0) is answered, configuration 1 (y > 0) fails: each exception kind gives its
// status there, no patches, and the overall status and message are that configuration's.
TEST(QueryAdapter, StatusPerExceptionKind) {
  struct Case {
    std::function<void()> fail;
    std::int8_t status;
    const char* reason;
  };
  const Case cases[] = {
      {[] { throw NoContactError("lifted"); }, wrc::contact_reply_t::NO_CONTACT, "lifted"},
      {[] { throw OutsideModelError("outside the box"); }, wrc::contact_reply_t::OUTSIDE_MODEL, "outside the box"},
      {[] { throw ContactConfigurationError("flange climb"); }, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION,
       "flange climb"},
      {[] { throw std::invalid_argument("bad value"); }, wrc::contact_reply_t::BAD_REQUEST, "bad value"},
      {[] { throw std::runtime_error("broken"); }, wrc::contact_reply_t::INTERNAL_ERROR, "broken"},
      {[] { throw 42; }, wrc::contact_reply_t::INTERNAL_ERROR, "unknown exception"},
  };
  for (const Case& c : cases) {
    const StubModel model(s1002_uic60(), c.fail);
    wrc::contact_query_t q = distinct_query();
    q.configurations[0].y = -0.002;
    q.configurations[1].y = 0.003;
    wrc::contact_reply_t reply{};
    contactd::evaluate_query(model, q, reply);
    const std::string name = protocol::contact_status_name(c.status);
    ASSERT_EQ(reply.results.size(), 2u) << name;
    EXPECT_EQ(reply.results[0].status, wrc::contact_reply_t::OK) << name;
    EXPECT_EQ(reply.results[0].num_patches, 2) << name;
    EXPECT_EQ(reply.results[1].status, c.status) << name;
    EXPECT_EQ(reply.results[1].num_patches, 0) << name;
    EXPECT_EQ(reply.status, c.status) << name;
    EXPECT_EQ(reply.message, std::string("configuration 1 (y=0.003, roll=0.00042, yaw=0.0026): ") + c.reason) << name;
  }
}

// The worst status of a batch wins, whatever the order: OUTSIDE_MODEL before IMPOSSIBLE_CONFIGURATION.
TEST(QueryAdapter, WorstStatusWins) {
  const StubModel model(s1002_uic60(), [] { throw ContactConfigurationError("climb"); });
  wrc::contact_query_t q = distinct_query();
  q.configurations[0].y = 0.001;  // fails: IMPOSSIBLE_CONFIGURATION
  q.configurations[1].y = -0.001;
  wrc::contact_reply_t reply{};
  contactd::evaluate_query(model, q, reply);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);
  EXPECT_EQ(reply.message.rfind("configuration 0 (y=0.001,", 0), 0u) << reply.message;
  EXPECT_LT(protocol::contact_status_severity(wrc::contact_reply_t::OUTSIDE_MODEL),
            protocol::contact_status_severity(wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION));
  EXPECT_STREQ(protocol::contact_status_name(wrc::contact_reply_t::OUTSIDE_MODEL), "OUTSIDE_MODEL");
  EXPECT_STREQ(protocol::contact_status_name(99), "UNKNOWN");
}

// Real models: the onepoint model answers a centred rigid wheelset (OK, two patches) and calls
// y = 50 mm (flange climbed over) IMPOSSIBLE_CONFIGURATION; an interp model tabulated over
// |y| <= 4 mm answers y = 1 mm and calls y = 6 mm (on the tread, but outside its table) OUTSIDE_MODEL.
TEST(QueryAdapter, StatusesOfRealModels) {
  wrc::contact_query_t q = distinct_query();
  q.formulation = wrc::contact_query_t::RIGID;
  for (auto& c : q.configurations) {
    c.z = 0.46;
    c.roll = 0.0;
    c.yaw = 0.0;
  }
  q.configurations[0].y = 0.0;
  q.configurations[1].y = 0.05;
  const auto onepoint = make_contact_model("onepoint", s1002_uic60());
  wrc::contact_reply_t reply{};
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_EQ(reply.results[0].status, wrc::contact_reply_t::OK) << reply.message;
  EXPECT_EQ(reply.results[0].num_patches, 2);
  EXPECT_EQ(reply.results[1].status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);

  ContactModelOptions small;
  small.interp.y_points = 9;
  small.interp.y_max = 0.004;
  small.interp.yaw_points = 2;
  const auto interp = make_contact_model("interp", s1002_uic60(), small);
  q.configurations[0].y = 0.001;
  q.configurations[1].y = 0.006;
  contactd::evaluate_query(*interp, q, reply);
  EXPECT_EQ(reply.results[0].status, wrc::contact_reply_t::OK) << reply.message;
  EXPECT_EQ(reply.results[1].status, wrc::contact_reply_t::OUTSIDE_MODEL);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::OUTSIDE_MODEL);
  EXPECT_NE(reply.message.find("configuration 1 (y=0.006"), std::string::npos) << reply.message;
}

// A configuration that follows an earlier one's answer (wheelset_configuration_t::follows) is
// answered as in-process (InProcessContact, the same rule), to the last bit: S1002 on UIC60 at
// 5.5 mm following the tread point answered at 5 mm, where the lowest point is another. One that
// follows a configuration without an answer is a BAD_REQUEST naming both.
TEST(QueryAdapter, FollowsAnEarlierConfigurationsAnswer) {
  wrc::contact_query_t q = distinct_query();
  q.formulation = wrc::contact_query_t::RIGID;
  for (auto& c : q.configurations) c.z = 0.46, c.roll = 0.0, c.yaw = 0.0, c.normal_load_left = c.normal_load_right = 8e4;
  q.configurations[0].y = 0.005;
  q.configurations[1].y = 0.0055;
  q.configurations[1].follows = 1;
  const std::shared_ptr<const ContactModel> onepoint = make_contact_model("onepoint", s1002_uic60());
  wrc::contact_reply_t reply{};
  contactd::evaluate_query(*onepoint, q, reply);
  ASSERT_EQ(reply.status, wrc::contact_reply_t::OK) << reply.message;
  InProcessContact in_process(onepoint);
  const std::vector<ContactResult> want = in_process.evaluate({to_contact_query(q, 0), to_contact_query(q, 1)});
  const ContactResult got = from_result_message(reply.results[1]);
  for (size_t w = 0; w < 2; ++w) {
    EXPECT_EQ(got.wheels[w].s_wheel, want[1].wheels[w].s_wheel) << "wheel " << w;
    EXPECT_EQ(got.wheels[w].gap, want[1].wheels[w].gap) << "wheel " << w;
  }
  q.configurations[1].follows = 0;  // the lowest point instead
  q.configurations[1].tracked_s_wheel_left = q.configurations[1].tracked_s_wheel_right =
      std::numeric_limits<double>::quiet_NaN();
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_NE(from_result_message(reply.results[1]).wheels[0].s_wheel, got.wheels[0].s_wheel) << "following matters here";

  // A follower of a configuration without an answer has that one's status, and the reply the
  // followed one's status and message (a run then sees IMPOSSIBLE_CONFIGURATION, as in-process).
  q.configurations[0].y = 0.05;
  q.configurations[1].follows = 1;
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_EQ(reply.results[0].status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);
  EXPECT_EQ(reply.results[1].status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION);
  EXPECT_EQ(reply.message.rfind("configuration 0 (y=0.05", 0), 0u) << reply.message;

  // A follows that names no earlier configuration is refused with the message, before any work.
  q.configurations[0].y = 0.005;
  for (const int bad : {2, -1, 300}) {
    q.configurations[1].follows = static_cast<std::int16_t>(bad);
    EXPECT_EQ(validate_query(q), "configurations[1].follows = " + std::to_string(bad) +
                                     " is neither 0 nor an earlier configuration's number plus 1 (1..1)");
  }
  q.configurations[1].follows = 1;
  EXPECT_EQ(validate_query(q), "");
  ContactQuery huge;
  huge.follows = 40000;
  wrc::wheelset_configuration_t c{};
  EXPECT_THROW(to_configuration_message(huge, c), std::invalid_argument);
}

// Real model, elastic formulation: a wheelset lowered 0.1 mm is answered, one 50 mm above its rails
// is NO_CONTACT and one 160 mm into them IMPOSSIBLE_CONFIGURATION, each with the reason.
TEST(QueryAdapter, ContactRangeOfARealModel) {
  wrc::contact_query_t q = distinct_query();
  q.formulation = wrc::contact_query_t::ELASTIC;
  q.num_configurations = 1;
  q.configurations.resize(1);
  wrc::wheelset_configuration_t& c = q.configurations[0];
  c.y = 0.0;
  c.roll = 0.0;
  c.yaw = 0.0;
  const auto onepoint = make_contact_model("onepoint", s1002_uic60());
  ContactQuery probe;
  probe.pose.z = 0.46;
  const ContactResult at_nominal = onepoint->evaluate(probe);
  const double touching = 0.46 - std::min(at_nominal.wheels[0].gap, at_nominal.wheels[1].gap);
  wrc::contact_reply_t reply{};
  c.z = touching - 1e-4;
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::OK) << reply.message;
  c.z = touching + 0.05;
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::NO_CONTACT) << reply.message;
  EXPECT_NE(reply.message.find("lifted"), std::string::npos) << reply.message;
  c.z = 0.3;
  contactd::evaluate_query(*onepoint, q, reply);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION) << reply.message;
  EXPECT_NE(reply.message.find("penetration"), std::string::npos) << reply.message;
}

}  // namespace
}  // namespace wrc::protocol
