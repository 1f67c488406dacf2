// SPDX-License-Identifier: Apache-2.0
#include "protocol/contact/contact_query_codec.hpp"

#include <cmath>
#include <exception>
#include <optional>
#include <stdexcept>

#include "core/model_interface/query_validation.hpp"
#include "core/numerics/number_text.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::protocol {

namespace {

// The message field of a library query field: its name, and whether it belongs to the whole
// query (material, grid) rather than to each configuration.
struct MessageField {
  const char* name;
  bool per_configuration;
};

MessageField message_field(QueryField field) {
  switch (field) {
    case QueryField::kPoseY: return {"y", true};
    case QueryField::kPoseZ: return {"z", true};
    case QueryField::kPoseRoll: return {"roll", true};
    case QueryField::kPoseYaw: return {"yaw", true};
    case QueryField::kPoseX: return {"x", true};  // not on the bus (always 0)
    case QueryField::kYDot: return {"y_dot", true};
    case QueryField::kZDot: return {"z_dot", true};
    case QueryField::kRollDot: return {"roll_dot", true};
    case QueryField::kYawDot: return {"yaw_dot", true};
    case QueryField::kSpinRate: return {"spin_rate", true};
    case QueryField::kSpeed: return {"speed", true};
    case QueryField::kNormalLoadLeft: return {"normal_load_left", true};
    case QueryField::kNormalLoadRight: return {"normal_load_right", true};
    case QueryField::kSecondNormalLoadLeft: return {"second_normal_load_left", true};
    case QueryField::kSecondNormalLoadRight: return {"second_normal_load_right", true};
    case QueryField::kTrackedSWheelLeft: return {"tracked_s_wheel_left", true};
    case QueryField::kTrackedSWheelRight: return {"tracked_s_wheel_right", true};
    case QueryField::kSecondTrackedSWheelLeft: return {"second_tracked_s_wheel_left", true};
    case QueryField::kSecondTrackedSWheelRight: return {"second_tracked_s_wheel_right", true};
    case QueryField::kFormulation: return {"formulation", false};
    case QueryField::kShearModulus: return {"shear_modulus", false};
    case QueryField::kPoissonRatio: return {"poisson_ratio", false};
    case QueryField::kFriction: return {"friction", false};
    case QueryField::kFastsimElements: return {"fastsim_elements", false};
    case QueryField::kFastsimStrips: return {"fastsim_strips", false};
    case QueryField::kRailLateralLeft: return {"rail_lateral[0]", true};
    case QueryField::kRailVerticalLeft: return {"rail_vertical[0]", true};
    case QueryField::kRailRollLeft: return {"rail_roll[0]", true};
    case QueryField::kRailLateralRateLeft: return {"rail_lateral_rate[0]", true};
    case QueryField::kRailVerticalRateLeft: return {"rail_vertical_rate[0]", true};
    case QueryField::kRailRollRateLeft: return {"rail_roll_rate[0]", true};
    case QueryField::kRailLateralRight: return {"rail_lateral[1]", true};
    case QueryField::kRailVerticalRight: return {"rail_vertical[1]", true};
    case QueryField::kRailRollRight: return {"rail_roll[1]", true};
    case QueryField::kRailLateralRateRight: return {"rail_lateral_rate[1]", true};
    case QueryField::kRailVerticalRateRight: return {"rail_vertical_rate[1]", true};
    case QueryField::kRailRollRateRight: return {"rail_roll_rate[1]", true};
  }
  return {"?", false};
}

void copy3(const Eigen::Vector3d& from, double to[3]) {
  for (int k = 0; k < 3; ++k) to[k] = from[k];
}

void to_constraint_message(const WheelConstraint& w, wrc::wheel_constraint_t& m) {
  m.gap = w.gap;
  for (int k = 0; k < 4; ++k) m.gap_gradient[k] = w.gap_gradient[k];
  m.gap_rate = w.gap_rate;
  m.normal_z = w.normal_z;
  m.s_wheel = w.s_wheel;
  m.contact_angle = w.contact_angle;
  m.switch_function = w.switch_function;
  m.switch_s_wheel = w.switch_s_wheel;
}

WheelConstraint from_constraint_message(const wrc::wheel_constraint_t& w) {
  WheelConstraint c;
  c.gap = w.gap;
  c.gap_gradient = Eigen::Vector4d(w.gap_gradient[0], w.gap_gradient[1], w.gap_gradient[2], w.gap_gradient[3]);
  c.gap_rate = w.gap_rate;
  c.normal_z = w.normal_z;
  c.s_wheel = w.s_wheel;
  c.contact_angle = w.contact_angle;
  c.switch_function = w.switch_function;
  c.switch_s_wheel = w.switch_s_wheel;
  return c;
}

}  // namespace

std::string validate_query(const wrc::contact_query_t& q) {
  // What a message alone needs: a known formulation, a batch size in range and as many
  // configurations as it says. Every value's range is the library's rule (find_query_violation).
  if (q.formulation != wrc::contact_query_t::RIGID && q.formulation != wrc::contact_query_t::ELASTIC) {
    return "formulation = " + std::to_string(q.formulation) + " is neither RIGID (0) nor ELASTIC (1)";
  }
  if (q.num_configurations < 1 || q.num_configurations > kMaxConfigurations) {
    return "num_configurations = " + std::to_string(q.num_configurations) + " is outside [1, " +
           std::to_string(kMaxConfigurations) + "]";
  }
  if (static_cast<std::size_t>(q.num_configurations) != q.configurations.size()) {
    return "num_configurations = " + std::to_string(q.num_configurations) + " but " +
           std::to_string(q.configurations.size()) + " configurations";
  }
  for (int i = 0; i < q.num_configurations; ++i) {
    const int follows = q.configurations[static_cast<std::size_t>(i)].follows;
    if (follows < 0 || follows > i) {
      return "configurations[" + std::to_string(i) + "].follows = " + std::to_string(follows) +
             " is neither 0 nor an earlier configuration's number plus 1 (1.." + std::to_string(i) + ")";
    }
    const std::optional<QueryViolation> violation = find_query_violation(to_contact_query(q, i));
    if (!violation) continue;
    // The field's full name is built only for the message of a bad value (hot path otherwise).
    const MessageField field = message_field(violation->rule.field);
    const std::string name =
        field.per_configuration ? "configurations[" + std::to_string(i) + "]." + field.name : field.name;
    return name + " = " + number_text(violation->value) + " " + query_rule_breach(*violation);
  }
  return {};
}

ContactQuery to_contact_query(const wrc::contact_query_t& q, int index) {
  const auto& c = q.configurations.at(static_cast<std::size_t>(index));
  ContactQuery out;
  out.pose.y = c.y;
  out.pose.z = c.z;
  out.pose.roll = c.roll;
  out.pose.yaw = c.yaw;
  out.y_dot = c.y_dot;
  out.z_dot = c.z_dot;
  out.roll_dot = c.roll_dot;
  out.yaw_dot = c.yaw_dot;
  out.spin_rate = c.spin_rate;
  out.speed = c.speed;
  out.normal_load = {c.normal_load_left, c.normal_load_right};
  out.formulation = q.formulation == wrc::contact_query_t::ELASTIC ? ContactFormulation::kElastic
                                                                   : ContactFormulation::kRigid;
  out.material.shear_modulus = q.shear_modulus;
  out.material.poisson_ratio = q.poisson_ratio;
  out.material.friction = q.friction;
  out.fastsim_elements = q.fastsim_elements;
  out.fastsim_strips = q.fastsim_strips;
  out.tracked_s_wheel = {c.tracked_s_wheel_left, c.tracked_s_wheel_right};
  out.second_tracked_s_wheel = {c.second_tracked_s_wheel_left, c.second_tracked_s_wheel_right};
  out.second_normal_load = {c.second_normal_load_left, c.second_normal_load_right};
  out.follows = c.follows;
  for (std::size_t i = 0; i < 2; ++i) {
    RailOffset& rail = out.rail_offsets[i];
    rail.lateral = c.rail_lateral[i];
    rail.vertical = c.rail_vertical[i];
    rail.roll = c.rail_roll[i];
    rail.lateral_rate = c.rail_lateral_rate[i];
    rail.vertical_rate = c.rail_vertical_rate[i];
    rail.roll_rate = c.rail_roll_rate[i];
  }
  return out;
}

void to_configuration_message(const ContactQuery& query, wrc::wheelset_configuration_t& c) {
  c.y = query.pose.y;
  c.z = query.pose.z;
  c.roll = query.pose.roll;
  c.yaw = query.pose.yaw;
  c.y_dot = query.y_dot;
  c.z_dot = query.z_dot;
  c.roll_dot = query.roll_dot;
  c.yaw_dot = query.yaw_dot;
  c.spin_rate = query.spin_rate;
  c.speed = query.speed;
  c.normal_load_left = query.normal_load[0];
  c.normal_load_right = query.normal_load[1];
  c.tracked_s_wheel_left = query.tracked_s_wheel[0];
  c.tracked_s_wheel_right = query.tracked_s_wheel[1];
  c.second_tracked_s_wheel_left = query.second_tracked_s_wheel[0];
  c.second_tracked_s_wheel_right = query.second_tracked_s_wheel[1];
  c.second_normal_load_left = query.second_normal_load[0];
  c.second_normal_load_right = query.second_normal_load[1];
  if (query.follows < 0 || query.follows > kMaxConfigurations)
    throw std::invalid_argument("to_configuration_message: follows = " + std::to_string(query.follows) +
                                " is outside [0, " + std::to_string(kMaxConfigurations) + "]");
  c.follows = static_cast<std::int16_t>(query.follows);
  for (std::size_t i = 0; i < 2; ++i) {
    const RailOffset& rail = query.rail_offsets[i];
    c.rail_lateral[i] = rail.lateral;
    c.rail_vertical[i] = rail.vertical;
    c.rail_roll[i] = rail.roll;
    c.rail_lateral_rate[i] = rail.lateral_rate;
    c.rail_vertical_rate[i] = rail.vertical_rate;
    c.rail_roll_rate[i] = rail.roll_rate;
  }
}

bool shares_query_fields(const ContactQuery& a, const ContactQuery& b) {
  return a.formulation == b.formulation && a.material.shear_modulus == b.material.shear_modulus &&
         a.material.poisson_ratio == b.material.poisson_ratio && a.material.friction == b.material.friction &&
         a.fastsim_elements == b.fastsim_elements && a.fastsim_strips == b.fastsim_strips;
}

void to_query_message(const std::vector<ContactQuery>& batch, wrc::contact_query_t& q) {
  if (batch.empty()) throw std::invalid_argument("to_query_message: empty batch");
  const ContactQuery& first = batch.front();
  for (std::size_t i = 1; i < batch.size(); ++i)
    if (!shares_query_fields(first, batch[i]))
      throw std::invalid_argument("to_query_message: query " + std::to_string(i) +
                                  " differs from the first in formulation, material or grid");
  q.formulation = first.formulation == ContactFormulation::kElastic ? wrc::contact_query_t::ELASTIC
                                                                    : wrc::contact_query_t::RIGID;
  q.shear_modulus = first.material.shear_modulus;
  q.poisson_ratio = first.material.poisson_ratio;
  q.friction = first.material.friction;
  q.fastsim_elements = static_cast<std::int16_t>(first.fastsim_elements);
  q.fastsim_strips = static_cast<std::int16_t>(first.fastsim_strips);
  q.num_configurations = static_cast<std::int32_t>(batch.size());
  q.configurations.assign(batch.size(), wrc::wheelset_configuration_t{});
  for (std::size_t i = 0; i < batch.size(); ++i) to_configuration_message(batch[i], q.configurations[i]);
}

void to_result_message(const ContactResult& result, wrc::contact_result_t& message) {
  message.status = wrc::contact_reply_t::OK;
  message.num_patches = static_cast<std::int32_t>(result.patches.size());
  message.patches.assign(result.patches.size(), wrc::contact_patch_t{});
  for (std::size_t i = 0; i < result.patches.size(); ++i) {
    const ContactPatch& p = result.patches[i];
    wrc::contact_patch_t& m = message.patches[i];
    m.wheel = p.point.side == WheelSide::kLeft ? wrc::contact_patch_t::LEFT : wrc::contact_patch_t::RIGHT;
    m.s_wheel = p.point.s;
    m.s_rail = p.point.s_rail;
    copy3(p.point.wheel_point, m.wheel_point);
    copy3(p.point.rail_point, m.rail_point);
    copy3(p.point.normal, m.normal);
    m.contact_angle = p.point.contact_angle;
    m.rolling_radius = p.point.rolling_radius;
    m.a = p.a;
    m.b = p.b;
    m.penetration = p.penetration;
    m.normal_force = p.normal_force;
    m.creepage_x = p.creepages.longitudinal;
    m.creepage_y = p.creepages.lateral;
    m.spin_creepage = p.creepages.spin;
    m.fx = p.forces.fx;
    m.fy = p.forces.fy;
    m.mz = p.forces.mz;
    m.lateral_curvature_floored = p.lateral_curvature_floored ? 1 : 0;
  }
  for (std::size_t i = 0; i < 2; ++i) to_constraint_message(result.wheels[i], message.wheels[i]);
  message.second_wheel_side.clear();
  message.second_wheels.clear();
  for (std::size_t i = 0; i < 2; ++i) {
    if (!result.second_wheels[i]) continue;
    message.second_wheel_side.push_back(i == 0 ? wrc::contact_patch_t::LEFT : wrc::contact_patch_t::RIGHT);
    message.second_wheels.emplace_back();
    to_constraint_message(*result.second_wheels[i], message.second_wheels.back());
  }
  message.num_second_wheels = static_cast<std::int8_t>(message.second_wheels.size());
  copy3(result.force, message.force);
  copy3(result.moment, message.moment);
  copy3(result.creep_force, message.creep_force);
  copy3(result.creep_moment, message.creep_moment);
}

ContactResult from_result_message(const wrc::contact_result_t& m) {
  auto vec3 = [](const double v[3]) { return Eigen::Vector3d(v[0], v[1], v[2]); };
  ContactResult r;
  r.patches.reserve(m.patches.size());
  for (const wrc::contact_patch_t& p : m.patches) {
    ContactPatch out;
    out.point.side = p.wheel == wrc::contact_patch_t::LEFT ? WheelSide::kLeft : WheelSide::kRight;
    out.point.s = p.s_wheel;
    out.point.s_rail = p.s_rail;
    out.point.wheel_point = vec3(p.wheel_point);
    out.point.rail_point = vec3(p.rail_point);
    out.point.normal = vec3(p.normal);
    out.point.contact_angle = p.contact_angle;
    out.point.rolling_radius = p.rolling_radius;
    out.point.is_minimum = true;
    out.a = p.a;
    out.b = p.b;
    out.penetration = p.penetration;
    out.normal_force = p.normal_force;
    out.creepages.longitudinal = p.creepage_x;
    out.creepages.lateral = p.creepage_y;
    out.creepages.spin = p.spin_creepage;
    out.forces.fx = p.fx;
    out.forces.fy = p.fy;
    out.forces.mz = p.mz;
    out.lateral_curvature_floored = p.lateral_curvature_floored != 0;
    r.patches.push_back(out);
  }
  for (std::size_t i = 0; i < 2; ++i) r.wheels[i] = from_constraint_message(m.wheels[i]);
  const std::size_t seconds = std::min(m.second_wheels.size(), m.second_wheel_side.size());
  for (std::size_t k = 0; k < seconds; ++k)
    r.second_wheels[m.second_wheel_side[k] == wrc::contact_patch_t::LEFT ? 0 : 1] =
        from_constraint_message(m.second_wheels[k]);
  r.force = vec3(m.force);
  r.moment = vec3(m.moment);
  r.creep_force = vec3(m.creep_force);
  r.creep_moment = vec3(m.creep_moment);
  return r;
}

}  // namespace wrc::protocol
