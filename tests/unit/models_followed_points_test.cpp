// SPDX-License-Identifier: Apache-2.0
// Following contact points inside one batch (core/model_interface/followed_points.hpp): a
// configuration that follows an earlier one's answer is answered as the caller would ask it after
// following that answer, to the last bit; it matters where the wheel has two minima (S1002 on
// UIC60 5.5 mm off centre: the tread point followed from 5 mm lies 10 mm from the lowest point, on
// the flange side); second points are followed only where the caller holds one; a follows that
// names no earlier configuration, or one without an answer, is refused naming both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/model_interface/followed_points.hpp"
#include "core/models/contact_model_factory.hpp"
#include "expect_invalid.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A rigid centred-height wheelset at lateral shift y [m], rolling, each wheel loaded with 80 kN.
ContactQuery rolling_at(double y) {
  ContactQuery q;
  q.pose.y = y;
  q.pose.z = 0.46;
  q.spin_rate = q.speed / 0.46;
  q.normal_load = {80e3, 80e3};
  return q;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(FollowedPoints, ABatchFollowsTheAnswerOfAnEarlierConfiguration) {
  const std::shared_ptr<const ContactModel> model = make_contact_model("onepoint", test::s1002_uic60_geometry());
  InProcessContact contact(model);
  ContactQuery next = rolling_at(0.0055);
  next.follows = 1;
  const std::vector<ContactResult> batch = contact.evaluate({rolling_at(0.005), next});
  ASSERT_EQ(batch.size(), 2u);

  // The caller's way: the answer at 5 mm, its points followed, then the query at 5.5 mm.
  const ContactResult first = model->evaluate(rolling_at(0.005));
  ContactQuery followed = rolling_at(0.0055);
  followed.tracked_s_wheel = {first.wheels[0].s_wheel, first.wheels[1].s_wheel};
  const ContactResult asked_after = model->evaluate(followed);
  for (size_t w = 0; w < 2; ++w) {
    EXPECT_TRUE(same_bits(batch[1].wheels[w].s_wheel, asked_after.wheels[w].s_wheel)) << "wheel " << w;
    EXPECT_TRUE(same_bits(batch[1].wheels[w].gap, asked_after.wheels[w].gap)) << "wheel " << w;
    EXPECT_TRUE(same_bits(batch[1].wheels[w].switch_function, asked_after.wheels[w].switch_function)) << "wheel " << w;
  }
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(batch[1].force[k], asked_after.force[k])) << "force " << k;

  // Without following, the left wheel's lowest point is another (flange-side) minimum.
  const ContactResult lowest = model->evaluate(rolling_at(0.0055));
  EXPECT_GT(std::abs(lowest.wheels[0].s_wheel - batch[1].wheels[0].s_wheel), 5e-3)
      << "lowest " << lowest.wheels[0].s_wheel << " m, followed " << batch[1].wheels[0].s_wheel << " m";
}

TEST(FollowedPoints, SecondPointsAreFollowedWhereTheCallerHoldsOne) {
  ContactResult answer;
  answer.wheels[0].s_wheel = 0.001;
  answer.wheels[1].s_wheel = -0.002;
  answer.second_wheels[0] = WheelConstraint{};
  answer.second_wheels[0]->s_wheel = -0.031;
  answer.second_wheels[1] = WheelConstraint{};
  answer.second_wheels[1]->s_wheel = 0.029;

  std::array<double, 2> tracked{0.5, 0.5};
  std::array<double, 2> second{-0.03, kNaN};  // a second point held on the left wheel only
  follow_answered_points(answer, tracked, second);
  EXPECT_EQ(tracked[0], 0.001);
  EXPECT_EQ(tracked[1], -0.002);
  EXPECT_EQ(second[0], -0.031);
  EXPECT_TRUE(std::isnan(second[1])) << "a second point the caller does not hold stays none";

  answer.second_wheels[0].reset();  // held, but not answered: kept
  second = {-0.03, kNaN};
  follow_answered_points(answer, tracked, second);
  EXPECT_EQ(second[0], -0.03);
}

TEST(FollowedPoints, AFollowsWithoutAnEarlierAnswerIsRefused) {
  ContactResult answer;
  answer.wheels[0].s_wheel = 0.004;
  const std::vector<const ContactResult*> one_answer{&answer};
  ContactQuery q;
  q.follows = 2;  // configuration 1 cannot follow itself
  test::expect_invalid([&] { apply_follows(one_answer, 1, q); }, "configuration 1: follows 2");
  q.follows = -1;
  test::expect_invalid([&] { apply_follows(one_answer, 1, q); }, "configuration 1: follows -1");
  q.follows = 1;
  test::expect_invalid([&] { apply_follows({nullptr}, 1, q); }, "configuration 0 has no answer");
  apply_follows(one_answer, 1, q);
  EXPECT_EQ(q.tracked_s_wheel[0], 0.004);
  ContactQuery untouched;
  apply_follows({}, 0, untouched);  // follows 0: nothing
  EXPECT_TRUE(std::isnan(untouched.tracked_s_wheel[0]));

  InProcessContact contact(make_contact_model("onepoint", test::s1002_uic60_geometry()));
  ContactQuery first = rolling_at(0.0);
  first.follows = 1;
  test::expect_invalid([&] { contact.evaluate({first}); }, "configuration 0: follows 1");
}

}  // namespace
}  // namespace wrc
