#include "protocol/contact/contact_query_codec.hpp"

#include <cmath>
#include <exception>
#include <stdexcept>

#include "core/geometry/wheelset_geometry.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/numerics/number_text.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::protocol {

namespace {

/// "" when value is finite and in [lo, hi], else "<name> = <value> is ...".
std::string check_range(const std::string& name, double value, double lo, double hi, const char* unit) {
  if (!std::isfinite(value)) return name + " = " + number_text(value) + " is not a finite number";
  if (value < lo || value > hi) {
    return name + " = " + number_text(value) + " is outside [" + number_text(lo) + ", " + number_text(hi) +
           "] " + unit;
  }
  return {};
}

std::string check_positive(const std::string& name, double value, double hi, const char* unit) {
  if (std::string why = check_range(name, value, 0.0, hi, unit); !why.empty()) return why;
  if (!(value > 0.0)) return name + " = " + number_text(value) + " is not positive";
  return {};
}

/// "" when value is finite and in the open interval (lo, hi), else "<name> = <value> is ...".
std::string check_open(const std::string& name, double value, double lo, double hi, const char* unit) {
  if (!std::isfinite(value)) return name + " = " + number_text(value) + " is not a finite number";
  if (!(value > lo && value < hi)) {
    return name + " = " + number_text(value) + " is outside (" + number_text(lo) + ", " + number_text(hi) +
           ") " + unit;
  }
  return {};
}

/// "" when count is in [kMinFastsimGrid, kMaxFastsimGrid] (the library's limits).
std::string check_grid(const char* name, std::int32_t count) {
  if (count >= wrc::kMinFastsimGrid && count <= wrc::kMaxFastsimGrid) return {};
  return std::string(name) + " = " + std::to_string(count) + " is outside [" + std::to_string(wrc::kMinFastsimGrid) +
         ", " + std::to_string(wrc::kMaxFastsimGrid) + "]";
}

std::string validate_configuration(const wrc::wheelset_configuration_t& c, int i, bool rigid) {
  struct Field {
    const char* name;
    double value;
    double lo, hi;
    const char* unit;
  };
  // Ranges of a wheelset that is on a track at all; whether a wheel touches its rail there is
  // for the model to say (IMPOSSIBLE_CONFIGURATION).
  const Field fields[] = {
      {"y", c.y, -0.5, 0.5, "m"},
      {"z", c.z, -10.0, 10.0, "m"},
      {"roll", c.roll, -0.5, 0.5, "rad"},
      {"yaw", c.yaw, -wrc::kMaxValidatedYaw, wrc::kMaxValidatedYaw, "rad"},  // validated geometry
      {"y_dot", c.y_dot, -100.0, 100.0, "m/s"},
      {"z_dot", c.z_dot, -100.0, 100.0, "m/s"},
      {"roll_dot", c.roll_dot, -100.0, 100.0, "rad/s"},
      {"yaw_dot", c.yaw_dot, -100.0, 100.0, "rad/s"},
      {"spin_rate", c.spin_rate, -1e4, 1e4, "rad/s"},
      {"normal_load_left", c.normal_load_left, rigid ? 0.0 : -1e300, rigid ? 1e8 : 1e300, "N"},
      {"normal_load_right", c.normal_load_right, rigid ? 0.0 : -1e300, rigid ? 1e8 : 1e300, "N"},
      {"second_normal_load_left", c.second_normal_load_left, rigid ? 0.0 : -1e300, rigid ? 1e8 : 1e300, "N"},
      {"second_normal_load_right", c.second_normal_load_right, rigid ? 0.0 : -1e300, rigid ? 1e8 : 1e300, "N"},
  };
  for (const Field& f : fields) {
    // The field's full name is built only for the message of a bad value (hot path otherwise).
    if (std::isfinite(f.value) && f.value >= f.lo && f.value <= f.hi) continue;
    return check_range("configurations[" + std::to_string(i) + "]." + f.name, f.value, f.lo, f.hi, f.unit);
  }
  // A tracked branch is a wheel profile coordinate, or NaN for none.
  const Field tracked[] = {{"tracked_s_wheel_left", c.tracked_s_wheel_left, -1.0, 1.0, "m"},
                           {"tracked_s_wheel_right", c.tracked_s_wheel_right, -1.0, 1.0, "m"},
                           {"second_tracked_s_wheel_left", c.second_tracked_s_wheel_left, -1.0, 1.0, "m"},
                           {"second_tracked_s_wheel_right", c.second_tracked_s_wheel_right, -1.0, 1.0, "m"}};
  for (const Field& f : tracked) {
    if (std::isnan(f.value) || (f.value >= f.lo && f.value <= f.hi)) continue;
    return check_range("configurations[" + std::to_string(i) + "]." + f.name, f.value, f.lo, f.hi, f.unit);
  }
  return {};
}


void copy3(const Eigen::Vector3d& from, double to[3]) {
  for (int k = 0; k < 3; ++k) to[k] = from[k];
}

void to_constraint_message(const WheelConstraint& w, wrc::wheel_constraint_t& m) {
  m.gap = w.gap;
  for (int k = 0; k < 4; ++k) m.gap_gradient[k] = w.gap_gradient[k];
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
  c.normal_z = w.normal_z;
  c.s_wheel = w.s_wheel;
  c.contact_angle = w.contact_angle;
  c.switch_function = w.switch_function;
  c.switch_s_wheel = w.switch_s_wheel;
  return c;
}

}  // namespace

std::string validate_query(const wrc::contact_query_t& q) {
  if (q.formulation != wrc::contact_query_t::RIGID && q.formulation != wrc::contact_query_t::ELASTIC) {
    return "formulation = " + std::to_string(q.formulation) + " is neither RIGID (0) nor ELASTIC (1)";
  }
  // Material, speed and grid limits are the library's (core/model_interface/query_validation.hpp).
  if (std::string why = check_positive("shear_modulus", q.shear_modulus, wrc::kMaxShearModulus, "Pa"); !why.empty()) {
    return why;
  }
  if (std::string why = check_open("poisson_ratio", q.poisson_ratio, wrc::kMinPoissonRatio, wrc::kMaxPoissonRatio, "[-]");
      !why.empty()) {
    return why;
  }
  if (std::string why = check_range("friction", q.friction, 0.0, wrc::kMaxFriction, "[-]"); !why.empty()) return why;
  if (std::string why = check_positive("speed", q.speed, wrc::kMaxSpeed, "m/s"); !why.empty()) return why;
  if (std::string why = check_grid("fastsim_elements", q.fastsim_elements); !why.empty()) return why;
  if (std::string why = check_grid("fastsim_strips", q.fastsim_strips); !why.empty()) return why;
  if (q.num_configurations < 1 || q.num_configurations > kMaxConfigurations) {
    return "num_configurations = " + std::to_string(q.num_configurations) + " is outside [1, " +
           std::to_string(kMaxConfigurations) + "]";
  }
  if (static_cast<std::size_t>(q.num_configurations) != q.configurations.size()) {
    return "num_configurations = " + std::to_string(q.num_configurations) + " but " +
           std::to_string(q.configurations.size()) + " configurations";
  }
  const bool rigid = q.formulation == wrc::contact_query_t::RIGID;
  for (int i = 0; i < q.num_configurations; ++i) {
    if (std::string why = validate_configuration(q.configurations[static_cast<std::size_t>(i)], i, rigid);
        !why.empty()) {
      return why;
    }
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
  out.speed = q.speed;
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
  c.normal_load_left = query.normal_load[0];
  c.normal_load_right = query.normal_load[1];
  c.tracked_s_wheel_left = query.tracked_s_wheel[0];
  c.tracked_s_wheel_right = query.tracked_s_wheel[1];
  c.second_tracked_s_wheel_left = query.second_tracked_s_wheel[0];
  c.second_tracked_s_wheel_right = query.second_tracked_s_wheel[1];
  c.second_normal_load_left = query.second_normal_load[0];
  c.second_normal_load_right = query.second_normal_load[1];
}

void to_query_message(const std::vector<ContactQuery>& batch, wrc::contact_query_t& q) {
  if (batch.empty()) throw std::invalid_argument("to_query_message: empty batch");
  const ContactQuery& first = batch.front();
  q.formulation = first.formulation == ContactFormulation::kElastic ? wrc::contact_query_t::ELASTIC
                                                                    : wrc::contact_query_t::RIGID;
  q.shear_modulus = first.material.shear_modulus;
  q.poisson_ratio = first.material.poisson_ratio;
  q.friction = first.material.friction;
  q.fastsim_elements = static_cast<std::int16_t>(first.fastsim_elements);
  q.fastsim_strips = static_cast<std::int16_t>(first.fastsim_strips);
  q.speed = first.speed;
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
