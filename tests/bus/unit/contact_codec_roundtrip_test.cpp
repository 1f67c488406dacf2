// SPDX-License-Identifier: Apache-2.0
/// @file
/// The contact query adapter (services/protocol/contact/contact_query_codec.hpp) both ways, for the
/// fields and functions contact_query_codec_test.cpp leaves out: to_query_message and
/// to_configuration_message (library query -> message, every field by its message name, the
/// tracked and second-point fields included), to_contact_query of what they wrote, and
/// from_result_message of what to_result_message wrote (patches, both WheelConstraints with every
/// field, the second points of two-point contact on either wheel, force, moment, creep force and
/// creep moment). Each message goes through its LCM encoding in between, as on the bus.
///
/// Every carried value is distinct from every other (checked), so a swapped field fails, and
/// distinct from its default, so a dropped one fails. Values are copied, never computed, so
/// equality is exact (EXPECT_EQ on doubles). The fields that are not on the bus are named and
/// must come back as their documented defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "protocol/contact/contact_query_codec.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::protocol {
namespace {

// Distinct, non-default values: n-th value of a sequence that never repeats, with a sign and a
// scale chosen by the caller (so that the numbers look like the field they fill).
class Distinct {
 public:
  double next(double scale) {
    ++n_;
    const double v = scale * (1.0 + 0.0173 * n_ + 1e-6 * n_ * n_);
    used_.push_back(v);
    return v;
  }
  // Every value handed out differs from every other one (and so a swap of two fields shows).
  void expect_all_distinct() const {
    const std::set<double> unique(used_.begin(), used_.end());
    EXPECT_EQ(unique.size(), used_.size()) << "the test's values are not all distinct";
  }

 private:
  int n_ = 0;
  std::vector<double> used_;
};

template <class Message>
Message through_lcm(const Message& m) {
  std::vector<unsigned char> buffer(static_cast<size_t>(m.getEncodedSize()));
  EXPECT_EQ(m.encode(buffer.data(), 0, static_cast<int>(buffer.size())), static_cast<int>(buffer.size()));
  Message out;
  EXPECT_EQ(out.decode(buffer.data(), 0, static_cast<int>(buffer.size())), static_cast<int>(buffer.size()));
  return out;
}

// Three configurations of one batch: shared formulation, material and grid; every
// per-configuration field distinct. Configuration 2 follows no branch on the right wheel and has
// no second point (NaN, the "none" value).
std::vector<ContactQuery> distinct_batch(Distinct& d, ContactFormulation formulation) {
  std::vector<ContactQuery> batch(3);
  const double g = d.next(7.9e10), nu = d.next(0.26), mu = d.next(0.31);
  for (size_t i = 0; i < batch.size(); ++i) {
    ContactQuery& q = batch[i];
    q.pose.y = d.next(1e-3);
    q.pose.z = d.next(0.46);
    q.pose.roll = d.next(-2e-4);
    q.pose.yaw = d.next(1.1e-3);
    q.y_dot = d.next(0.02);
    q.z_dot = d.next(-0.003);
    q.roll_dot = d.next(0.004);
    q.yaw_dot = d.next(-0.005);
    q.spin_rate = d.next(-65.0);
    q.speed = d.next(27.0);  // per configuration (a curve's forward speed depends on y)
    q.normal_load = {d.next(7.1e4), d.next(6.9e4)};
    q.formulation = formulation;
    q.material = {g, nu, mu};
    q.fastsim_elements = 23;
    q.fastsim_strips = 17;
    q.tracked_s_wheel = {d.next(1e-3), i == 2 ? std::numeric_limits<double>::quiet_NaN() : d.next(-2e-3)};
    q.second_tracked_s_wheel = {d.next(-0.03), i == 2 ? std::numeric_limits<double>::quiet_NaN() : d.next(0.031)};
    q.second_normal_load = {d.next(1.2e3), i == 2 ? 0.0 : d.next(2.3e3)};
    for (RailOffset& r : q.rail_offsets)
      r = {d.next(1.1e-3), d.next(-0.7e-3), d.next(2.1e-3), d.next(0.013), d.next(-0.021), d.next(0.0031)};
    q.follows = static_cast<int>(i);  // 0 (none), then the configurations before
  }
  return batch;
}

// a == b for doubles, NaN equal to NaN (the "none" of the tracked fields).
void expect_same(double a, double b, const std::string& what) {
  if (std::isnan(b)) {
    EXPECT_TRUE(std::isnan(a)) << what << " = " << a << ", expected NaN";
  } else {
    EXPECT_EQ(a, b) << what;
  }
}

// Every field of a library query that the bus carries, and the one it does not (pose.x: the rail
// is prismatic, so no contact quantity depends on it; to_contact_query leaves it 0).
void expect_same_query(const ContactQuery& got, const ContactQuery& want, const std::string& at) {
  expect_same(got.pose.y, want.pose.y, at + "pose.y");
  expect_same(got.pose.z, want.pose.z, at + "pose.z");
  expect_same(got.pose.roll, want.pose.roll, at + "pose.roll");
  expect_same(got.pose.yaw, want.pose.yaw, at + "pose.yaw");
  EXPECT_EQ(got.pose.x, 0.0) << at << "pose.x (not on the bus)";
  expect_same(got.y_dot, want.y_dot, at + "y_dot");
  expect_same(got.z_dot, want.z_dot, at + "z_dot");
  expect_same(got.roll_dot, want.roll_dot, at + "roll_dot");
  expect_same(got.yaw_dot, want.yaw_dot, at + "yaw_dot");
  expect_same(got.spin_rate, want.spin_rate, at + "spin_rate");
  expect_same(got.speed, want.speed, at + "speed");
  EXPECT_EQ(got.formulation, want.formulation) << at << "formulation";
  expect_same(got.material.shear_modulus, want.material.shear_modulus, at + "shear_modulus");
  expect_same(got.material.poisson_ratio, want.material.poisson_ratio, at + "poisson_ratio");
  expect_same(got.material.friction, want.material.friction, at + "friction");
  EXPECT_EQ(got.fastsim_elements, want.fastsim_elements) << at << "fastsim_elements";
  EXPECT_EQ(got.fastsim_strips, want.fastsim_strips) << at << "fastsim_strips";
  EXPECT_EQ(got.follows, want.follows) << at << "follows";
  for (int w = 0; w < 2; ++w) {
    const std::string side = w == 0 ? "[left]" : "[right]";
    expect_same(got.normal_load[w], want.normal_load[w], at + "normal_load" + side);
    expect_same(got.tracked_s_wheel[w], want.tracked_s_wheel[w], at + "tracked_s_wheel" + side);
    expect_same(got.second_tracked_s_wheel[w], want.second_tracked_s_wheel[w], at + "second_tracked_s_wheel" + side);
    expect_same(got.second_normal_load[w], want.second_normal_load[w], at + "second_normal_load" + side);
    const RailOffset& g = got.rail_offsets[w];
    const RailOffset& r = want.rail_offsets[w];
    expect_same(g.lateral, r.lateral, at + "rail_offsets.lateral" + side);
    expect_same(g.vertical, r.vertical, at + "rail_offsets.vertical" + side);
    expect_same(g.roll, r.roll, at + "rail_offsets.roll" + side);
    expect_same(g.lateral_rate, r.lateral_rate, at + "rail_offsets.lateral_rate" + side);
    expect_same(g.vertical_rate, r.vertical_rate, at + "rail_offsets.vertical_rate" + side);
    expect_same(g.roll_rate, r.roll_rate, at + "rail_offsets.roll_rate" + side);
  }
}

// to_configuration_message: each library field in the message field of its name (a left/right
// swap made the same way in both directions would pass a round trip; this does not).
TEST(ContactCodecRoundTrip, ConfigurationMessageFieldsByName) {
  Distinct d;
  const ContactQuery q = distinct_batch(d, ContactFormulation::kRigid)[0];
  d.expect_all_distinct();
  wrc::wheelset_configuration_t c{};
  to_configuration_message(q, c);
  EXPECT_EQ(c.y, q.pose.y);
  EXPECT_EQ(c.z, q.pose.z);
  EXPECT_EQ(c.roll, q.pose.roll);
  EXPECT_EQ(c.yaw, q.pose.yaw);
  EXPECT_EQ(c.y_dot, q.y_dot);
  EXPECT_EQ(c.z_dot, q.z_dot);
  EXPECT_EQ(c.roll_dot, q.roll_dot);
  EXPECT_EQ(c.yaw_dot, q.yaw_dot);
  EXPECT_EQ(c.spin_rate, q.spin_rate);
  EXPECT_EQ(c.normal_load_left, q.normal_load[0]);
  EXPECT_EQ(c.normal_load_right, q.normal_load[1]);
  EXPECT_EQ(c.tracked_s_wheel_left, q.tracked_s_wheel[0]);
  EXPECT_EQ(c.tracked_s_wheel_right, q.tracked_s_wheel[1]);
  EXPECT_EQ(c.second_tracked_s_wheel_left, q.second_tracked_s_wheel[0]);
  EXPECT_EQ(c.second_tracked_s_wheel_right, q.second_tracked_s_wheel[1]);
  EXPECT_EQ(c.second_normal_load_left, q.second_normal_load[0]);
  EXPECT_EQ(c.second_normal_load_right, q.second_normal_load[1]);
  const ContactQuery q2 = distinct_batch(d, ContactFormulation::kRigid)[2];
  to_configuration_message(q2, c);
  EXPECT_EQ(c.follows, 2);
}

// to_query_message: the shared fields from the first query under their message names, one
// configuration per query in order, the addressing fields (header, request id, client, reply
// channel, model, instance, geometry key) left as they were; then through LCM and back with
// to_contact_query, every configuration equal to its query. Both formulations.
TEST(ContactCodecRoundTrip, QueryBatchThereAndBack) {
  for (const ContactFormulation formulation : {ContactFormulation::kRigid, ContactFormulation::kElastic}) {
    Distinct d;
    const std::vector<ContactQuery> batch = distinct_batch(d, formulation);
    d.expect_all_distinct();
    wrc::contact_query_t m{};
    m.request_id = 4711;
    m.client_id = "client";
    m.reply_channel = "P.CONTACT_REPLY.client";
    m.model = "interp";
    m.instance = "b";
    m.geometry_key = "0123abcd";
    m.header.seq = 99;
    to_query_message(batch, m);
    EXPECT_EQ(m.request_id, 4711);
    EXPECT_EQ(m.client_id, "client");
    EXPECT_EQ(m.reply_channel, "P.CONTACT_REPLY.client");
    EXPECT_EQ(m.model, "interp");
    EXPECT_EQ(m.instance, "b");
    EXPECT_EQ(m.geometry_key, "0123abcd");
    EXPECT_EQ(m.header.seq, 99);
    EXPECT_EQ(m.formulation, formulation == ContactFormulation::kElastic ? wrc::contact_query_t::ELASTIC
                                                                         : wrc::contact_query_t::RIGID);
    EXPECT_EQ(m.shear_modulus, batch[0].material.shear_modulus);
    EXPECT_EQ(m.poisson_ratio, batch[0].material.poisson_ratio);
    EXPECT_EQ(m.friction, batch[0].material.friction);
    EXPECT_EQ(m.fastsim_elements, 23);
    EXPECT_EQ(m.fastsim_strips, 17);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m.configurations[static_cast<size_t>(i)].speed, batch[static_cast<size_t>(i)].speed);
    ASSERT_EQ(m.num_configurations, 3);
    ASSERT_EQ(m.configurations.size(), 3u);
    EXPECT_EQ(m.configurations[1].y, batch[1].pose.y);  // in order
    const wrc::contact_query_t received = through_lcm(m);
    for (int i = 0; i < 3; ++i)
      expect_same_query(to_contact_query(received, i), batch[static_cast<size_t>(i)],
                        "configuration " + std::to_string(i) + ": ");
  }
}

// A batch is never empty, and its queries share what the message carries once: to_query_message
// refuses an empty batch and one whose friction differs (BusContact sends such a batch as one
// message per run of queries that share them); speeds may differ (each configuration has its own).
TEST(ContactCodecRoundTrip, EmptyOrMixedBatchIsRefused) {
  wrc::contact_query_t m{};
  EXPECT_THROW(to_query_message({}, m), std::invalid_argument);
  Distinct d;
  std::vector<ContactQuery> batch = distinct_batch(d, ContactFormulation::kRigid);
  EXPECT_TRUE(shares_query_fields(batch[0], batch[2]));
  EXPECT_NE(batch[0].speed, batch[2].speed);
  batch[2].material.friction *= 1.0 + 1e-15;
  EXPECT_FALSE(shares_query_fields(batch[0], batch[2]));
  EXPECT_THROW(to_query_message(batch, m), std::invalid_argument);
}

WheelConstraint distinct_constraint(Distinct& d) {
  WheelConstraint w;
  w.gap = d.next(-1.3e-5);
  w.gap_gradient = {d.next(0.11), d.next(1.01), d.next(0.75), d.next(-0.012)};
  w.normal_z = d.next(0.97);
  w.gap_rate = d.next(-2.7e-4);
  w.s_wheel = d.next(2.1e-3);
  w.contact_angle = d.next(0.043);
  w.switch_function = d.next(4.4e-4);
  w.switch_s_wheel = d.next(-0.029);
  return w;
}

ContactPatch distinct_patch(Distinct& d, WheelSide side) {
  ContactPatch p;
  p.point.side = side;
  p.point.s = d.next(1.5e-3);
  p.point.s_rail = d.next(-2.5e-3);
  p.point.wheel_point = {d.next(1e-4), d.next(0.75), d.next(-1e-3)};
  p.point.rail_point = {d.next(2e-4), d.next(0.74), d.next(-1.1e-3)};
  p.point.normal = {d.next(1e-3), d.next(-0.04), d.next(0.999)};
  p.point.contact_angle = d.next(0.041);
  p.point.rolling_radius = d.next(0.46);
  p.a = d.next(6e-3);
  p.b = d.next(5e-3);
  p.penetration = d.next(8e-5);
  p.normal_force = d.next(7.3e4);
  p.creepages = {d.next(1e-4), d.next(-2e-4), d.next(0.03)};
  p.forces.fx = d.next(-1.3e3);
  p.forces.fy = d.next(2.4e3);
  p.forces.mz = d.next(-3.5);
  p.lateral_curvature_floored = side == WheelSide::kRight;
  return p;
}

void expect_same_constraint(const WheelConstraint& got, const WheelConstraint& want, const std::string& at) {
  EXPECT_EQ(got.gap, want.gap) << at << ".gap";
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got.gap_gradient[k], want.gap_gradient[k]) << at << ".gap_gradient[" << k << "]";
  EXPECT_EQ(got.normal_z, want.normal_z) << at << ".normal_z";
  EXPECT_EQ(got.gap_rate, want.gap_rate) << at << ".gap_rate";
  EXPECT_EQ(got.s_wheel, want.s_wheel) << at << ".s_wheel";
  EXPECT_EQ(got.contact_angle, want.contact_angle) << at << ".contact_angle";
  EXPECT_EQ(got.switch_function, want.switch_function) << at << ".switch_function";
  EXPECT_EQ(got.switch_s_wheel, want.switch_s_wheel) << at << ".switch_s_wheel";
}

void expect_same_vector(const Eigen::Vector3d& got, const Eigen::Vector3d& want, const std::string& at) {
  for (int k = 0; k < 3; ++k) EXPECT_EQ(got[k], want[k]) << at << "[" << k << "]";
}

// ContactResult -> to_result_message -> LCM -> from_result_message: every patch field (three
// patches, two on the right wheel as the multipoint model gives them), both wheels' constraints,
// the second points (none, left only, right only, both: each lands on its own wheel), force,
// moment, creep force and creep moment. Not on the bus and documented to come back as defaults:
// the point's curvatures (0), theta (0), distance (0), is_minimum (true: only minima are
// answered) and the forces' slip fraction (0).
TEST(ContactCodecRoundTrip, ResultThereAndBack) {
  for (const int seconds : {0, 1, 2, 3}) {  // bit 0: left wheel has a second point, bit 1: right
    Distinct d;
    ContactResult r;
    r.patches = {distinct_patch(d, WheelSide::kLeft), distinct_patch(d, WheelSide::kRight),
                 distinct_patch(d, WheelSide::kRight)};
    r.wheels = {distinct_constraint(d), distinct_constraint(d)};
    if (seconds & 1) r.second_wheels[0] = distinct_constraint(d);
    if (seconds & 2) r.second_wheels[1] = distinct_constraint(d);
    r.force = {d.next(12.0), d.next(-3.1e3), d.next(1.47e5)};
    r.moment = {d.next(-45.0), d.next(6.7), d.next(89.0)};
    r.creep_force = {d.next(-21.0), d.next(2.9e3), d.next(-32.0)};
    r.creep_moment = {d.next(43.0), d.next(-5.4), d.next(-76.0)};
    d.expect_all_distinct();
    // Patch values that are not on the bus: set, so that a result that kept them would show.
    for (ContactPatch& p : r.patches) {
      p.point.theta = 0.5;
      p.point.distance = -1e-5;
      p.point.wheel_curvature_lateral = 3.0;
      p.point.wheel_curvature_rolling = 2.0;
      p.point.rail_curvature_lateral = 4.0;
      p.point.rail_curvature_rolling = 1.0;
      p.point.distance_curvature = 5.0;
      p.point.is_minimum = false;
      p.forces.slip_fraction = 0.25;
    }

    wrc::contact_result_t m{};
    m.status = wrc::contact_reply_t::INTERNAL_ERROR;
    to_result_message(r, m);
    EXPECT_EQ(m.status, wrc::contact_reply_t::OK);
    // The message fields by name for what the existing test does not cover.
    for (size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(m.wheels[i].gap, r.wheels[i].gap);
      EXPECT_EQ(m.wheels[i].switch_s_wheel, r.wheels[i].switch_s_wheel);
    }
    EXPECT_EQ(m.num_second_wheels, (seconds & 1) + ((seconds & 2) >> 1));
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(m.creep_force[k], r.creep_force[k]);
      EXPECT_EQ(m.creep_moment[k], r.creep_moment[k]);
    }

    const ContactResult back = from_result_message(through_lcm(m));
    const std::string at = "seconds " + std::to_string(seconds) + ": ";
    ASSERT_EQ(back.patches.size(), r.patches.size()) << at;
    for (size_t i = 0; i < r.patches.size(); ++i) {
      const ContactPatch &got = back.patches[i], &want = r.patches[i];
      const std::string p = at + "patches[" + std::to_string(i) + "].";
      EXPECT_EQ(got.point.side, want.point.side) << p << "side";
      EXPECT_EQ(got.point.s, want.point.s) << p << "s";
      EXPECT_EQ(got.point.s_rail, want.point.s_rail) << p << "s_rail";
      expect_same_vector(got.point.wheel_point, want.point.wheel_point, p + "wheel_point");
      expect_same_vector(got.point.rail_point, want.point.rail_point, p + "rail_point");
      expect_same_vector(got.point.normal, want.point.normal, p + "normal");
      EXPECT_EQ(got.point.contact_angle, want.point.contact_angle) << p << "contact_angle";
      EXPECT_EQ(got.point.rolling_radius, want.point.rolling_radius) << p << "rolling_radius";
      EXPECT_EQ(got.a, want.a) << p << "a";
      EXPECT_EQ(got.b, want.b) << p << "b";
      EXPECT_EQ(got.penetration, want.penetration) << p << "penetration";
      EXPECT_EQ(got.normal_force, want.normal_force) << p << "normal_force";
      EXPECT_EQ(got.creepages.longitudinal, want.creepages.longitudinal) << p << "creepages.longitudinal";
      EXPECT_EQ(got.creepages.lateral, want.creepages.lateral) << p << "creepages.lateral";
      EXPECT_EQ(got.creepages.spin, want.creepages.spin) << p << "creepages.spin";
      EXPECT_EQ(got.forces.fx, want.forces.fx) << p << "fx";
      EXPECT_EQ(got.forces.fy, want.forces.fy) << p << "fy";
      EXPECT_EQ(got.forces.mz, want.forces.mz) << p << "mz";
      EXPECT_EQ(got.lateral_curvature_floored, want.lateral_curvature_floored) << p << "lateral_curvature_floored";
      // Not on the bus.
      EXPECT_EQ(got.point.theta, 0.0) << p;
      EXPECT_EQ(got.point.distance, 0.0) << p;
      EXPECT_EQ(got.point.wheel_curvature_lateral, 0.0) << p;
      EXPECT_EQ(got.point.wheel_curvature_rolling, 0.0) << p;
      EXPECT_EQ(got.point.rail_curvature_lateral, 0.0) << p;
      EXPECT_EQ(got.point.rail_curvature_rolling, 0.0) << p;
      EXPECT_EQ(got.point.distance_curvature, 0.0) << p;
      EXPECT_TRUE(got.point.is_minimum) << p;
      EXPECT_EQ(got.forces.slip_fraction, 0.0) << p;
    }
    for (size_t i = 0; i < 2; ++i) {
      const std::string w = at + (i == 0 ? "wheels[left]" : "wheels[right]");
      expect_same_constraint(back.wheels[i], r.wheels[i], w);
      ASSERT_EQ(back.second_wheels[i].has_value(), r.second_wheels[i].has_value()) << at << "second_wheels[" << i << "]";
      if (r.second_wheels[i])
        expect_same_constraint(*back.second_wheels[i], *r.second_wheels[i], at + "second_wheels[" + std::to_string(i) + "]");
    }
    expect_same_vector(back.force, r.force, at + "force");
    expect_same_vector(back.moment, r.moment, at + "moment");
    expect_same_vector(back.creep_force, r.creep_force, at + "creep_force");
    expect_same_vector(back.creep_moment, r.creep_moment, at + "creep_moment");
  }
}

}  // namespace
}  // namespace wrc::protocol
