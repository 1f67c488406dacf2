// SPDX-License-Identifier: Apache-2.0
/// @file
/// Rigid two-point contact over the bus (services/protocol/contact/contact_query_codec.hpp): the second point
/// of each wheel (its tracked s and load in wheelset_configuration_t, its constraint in
/// contact_result_t) lands in its own library field both ways, is absent when the library has
/// none, a bad second load or tracked s is named, and the real one-point model answers a
/// two-point query through the message the way it answers in-process.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "contactd/query_evaluation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "protocol/contact/contact_query_codec.hpp"

namespace wrc::protocol {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

wrc::contact_query_t rigid_query() {
  wrc::contact_query_t q{};
  q.model = "onepoint";
  q.formulation = wrc::contact_query_t::RIGID;
  q.shear_modulus = 8.2e10;
  q.poisson_ratio = 0.28;
  q.friction = 0.3;
  q.fastsim_elements = 20;
  q.fastsim_strips = 20;
  q.num_configurations = 1;
  wrc::wheelset_configuration_t c{};
  c.z = 0.46;
  c.spin_rate = 30.0 / 0.46;
  c.speed = 30.0;
  c.normal_load_left = 71000.0;
  c.normal_load_right = 69000.0;
  c.tracked_s_wheel_left = 0.0031;
  c.tracked_s_wheel_right = -0.0283;
  c.second_tracked_s_wheel_left = kNaN;
  c.second_tracked_s_wheel_right = -0.0171;
  c.second_normal_load_left = 0.0;
  c.second_normal_load_right = 23000.0;
  q.configurations.push_back(c);
  return q;
}

TEST(TwoPointCodec, SecondPointOfTheQueryLandsInItsLibraryField) {
  const wrc::contact_query_t q = rigid_query();
  ASSERT_EQ(validate_query(q), "");
  const ContactQuery l = to_contact_query(q, 0);
  EXPECT_TRUE(std::isnan(l.second_tracked_s_wheel[0]));
  EXPECT_EQ(l.second_tracked_s_wheel[1], -0.0171);
  EXPECT_EQ(l.second_normal_load[0], 0.0);
  EXPECT_EQ(l.second_normal_load[1], 23000.0);
  wrc::wheelset_configuration_t back{};
  to_configuration_message(l, back);
  EXPECT_TRUE(std::isnan(back.second_tracked_s_wheel_left));
  EXPECT_EQ(back.second_tracked_s_wheel_right, -0.0171);
  EXPECT_EQ(back.second_normal_load_right, 23000.0);
}

TEST(TwoPointCodec, BadSecondPointIsNamed) {
  wrc::contact_query_t q = rigid_query();
  q.configurations[0].second_normal_load_right = -1.0;
  EXPECT_NE(validate_query(q).find("configurations[0].second_normal_load_right"), std::string::npos)
      << validate_query(q);
  q = rigid_query();
  q.configurations[0].second_tracked_s_wheel_left = std::numeric_limits<double>::infinity();
  EXPECT_NE(validate_query(q).find("configurations[0].second_tracked_s_wheel_left"), std::string::npos)
      << validate_query(q);
}

TEST(TwoPointCodec, SecondConstraintRoundTripsAndIsAbsentWithoutOne) {
  ContactResult r;
  WheelConstraint second;
  second.gap = 1.5e-9;
  second.gap_gradient = {0.31, 1.0, -0.72, 0.04};
  second.normal_z = 0.93;
  second.s_wheel = -0.0171;
  second.contact_angle = 0.12;
  r.second_wheels[1] = second;
  wrc::contact_result_t m{};
  to_result_message(r, m);
  ASSERT_EQ(m.num_second_wheels, 1);
  EXPECT_EQ(m.second_wheel_side[0], wrc::contact_patch_t::RIGHT);
  const ContactResult back = from_result_message(m);
  EXPECT_FALSE(back.second_wheels[0].has_value());
  ASSERT_TRUE(back.second_wheels[1].has_value());
  EXPECT_EQ(back.second_wheels[1]->gap, 1.5e-9);
  EXPECT_EQ(back.second_wheels[1]->gap_gradient, second.gap_gradient);
  EXPECT_EQ(back.second_wheels[1]->normal_z, 0.93);
  EXPECT_EQ(back.second_wheels[1]->s_wheel, -0.0171);
  EXPECT_EQ(back.second_wheels[1]->contact_angle, 0.12);
  wrc::contact_result_t none{};
  to_result_message(ContactResult{}, none);
  EXPECT_EQ(none.num_second_wheels, 0);
  EXPECT_FALSE(from_result_message(none).second_wheels[1].has_value());
}

// S1002/UIC60 at y = -5 mm, yaw 0.8 mrad: the right wheel has its tread and flange-root minima
// within 0.1 mm of height; a two-point query through the message answers what the model answers.
TEST(TwoPointCodec, OnePointModelAnswersTheSameThroughTheMessage) {
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                                 make_profile("UIC60", ProfileSide::kRail));
  const auto model = make_contact_model("onepoint", geometry);
  wrc::contact_query_t q = rigid_query();
  q.configurations[0].y = -0.005;
  q.configurations[0].yaw = 0.0008;
  q.configurations[0].roll = -0.00034;
  q.configurations[0].tracked_s_wheel_left = kNaN;
  wrc::contact_reply_t reply{};
  contactd::evaluate_query(*model, q, reply);
  ASSERT_EQ(reply.status, wrc::contact_reply_t::OK) << reply.message;
  const ContactResult direct = model->evaluate(to_contact_query(q, 0));
  const ContactResult through = from_result_message(reply.results[0]);
  ASSERT_TRUE(direct.second_wheels[1].has_value());
  ASSERT_TRUE(through.second_wheels[1].has_value());
  EXPECT_FALSE(through.second_wheels[0].has_value());
  EXPECT_EQ(through.second_wheels[1]->gap, direct.second_wheels[1]->gap);
  EXPECT_EQ(through.second_wheels[1]->s_wheel, direct.second_wheels[1]->s_wheel);
  EXPECT_EQ(through.patches.size(), 3u);  // left, and both points of the right wheel
}

}  // namespace
}  // namespace wrc::protocol
