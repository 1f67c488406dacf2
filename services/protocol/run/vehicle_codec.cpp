// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/vehicle_codec.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wrc::protocol {
namespace {

void check_count(const char* field, long count, std::size_t listed, std::size_t limit) {
  const std::string c = std::string(field) + " = " + std::to_string(count);
  if (count < 0) throw std::invalid_argument(c + " is negative");
  if (static_cast<std::size_t>(count) > limit)
    throw std::invalid_argument(c + " is more than the limit of " + std::to_string(limit));
  if (static_cast<std::size_t>(count) != listed)
    throw std::invalid_argument(c + " does not match the " + std::to_string(listed) + " entries of its list");
}

void check_limit(const char* what, std::size_t count, std::size_t limit) {
  if (count > limit)
    throw std::invalid_argument(std::string("vehicle: ") + std::to_string(count) + " " + what + ", a run takes at most " +
                                std::to_string(limit));
}

template <std::size_t N>
void copy3(const std::array<double, N>& from, double (&to)[N]) {
  std::copy(from.begin(), from.end(), to);
}
template <std::size_t N>
std::array<double, N> array_of(const double (&from)[N]) {
  std::array<double, N> a{};
  std::copy(from, from + N, a.begin());
  return a;
}

}  // namespace

void to_vehicle_fields(const std::optional<VehicleDescription>& vehicle, run_command_t& m) {
  m.vehicle_name.clear();
  m.vehicle_bodies.clear();
  m.vehicle_elements.clear();
  m.num_vehicle_bodies = 0;
  m.num_vehicle_elements = 0;
  if (!vehicle) return;
  check_limit("bodies", vehicle->bodies.size(), kMaxVehicleBodies);
  check_limit("elements", vehicle->elements.size(), kMaxVehicleElements);
  m.vehicle_name = vehicle->name;
  for (const VehicleBody& b : vehicle->bodies) {
    vehicle_body_t t{};
    t.name = b.name;
    t.kind = static_cast<std::int8_t>(b.kind);
    t.mass = b.mass;
    copy3(b.inertia, t.inertia);
    copy3(b.products_of_inertia, t.products_of_inertia);
    copy3(b.position, t.position);
    copy3(b.external_force, t.external_force);
    m.vehicle_bodies.push_back(t);
  }
  for (const VehicleElement& e : vehicle->elements) {
    check_limit(("points in the curve of element '" + e.name + "'").c_str(), e.curve.size(), kMaxDamperCurvePoints);
    vehicle_element_t t{};
    t.name = e.name;
    t.kind = static_cast<std::int8_t>(e.kind);
    t.body_a = e.bodies[0];
    t.body_b = e.bodies[1];
    copy3(e.attachments[0], t.attachment_a);
    copy3(e.attachments[1], t.attachment_b);
    copy3(e.stiffness, t.stiffness);
    copy3(e.damping, t.damping);
    t.yaw_stiffness = e.yaw_stiffness;
    t.roll_stiffness = e.roll_stiffness;
    t.yaw_damping = e.yaw_damping;
    t.roll_damping = e.roll_damping;
    t.direction = static_cast<std::int8_t>(e.direction);
    t.clearance = e.clearance;
    t.stop_stiffness = e.stop_stiffness;
    t.num_curve_points = static_cast<std::int16_t>(e.curve.size());
    for (const auto& [v, f] : e.curve) {
      t.curve_velocity.push_back(v);
      t.curve_force.push_back(f);
    }
    m.vehicle_elements.push_back(t);
  }
  m.num_vehicle_bodies = static_cast<std::int16_t>(m.vehicle_bodies.size());
  m.num_vehicle_elements = static_cast<std::int16_t>(m.vehicle_elements.size());
}

std::optional<VehicleDescription> vehicle_from_fields(const run_command_t& m) {
  check_count("num_vehicle_bodies", m.num_vehicle_bodies, m.vehicle_bodies.size(), kMaxVehicleBodies);
  check_count("num_vehicle_elements", m.num_vehicle_elements, m.vehicle_elements.size(), kMaxVehicleElements);
  if (m.vehicle_bodies.empty()) {
    if (!m.vehicle_elements.empty()) throw std::invalid_argument("vehicle: elements without bodies");
    return std::nullopt;
  }
  VehicleDescription v;
  v.name = m.vehicle_name;
  for (const vehicle_body_t& t : m.vehicle_bodies) {
    if (t.kind < vehicle_body_t::CAR_BODY || t.kind > vehicle_body_t::WHEELSET)
      throw std::invalid_argument("vehicle: body '" + t.name + "': kind: " + std::to_string(t.kind) + " is none of " +
                                  "CAR_BODY, BOGIE_FRAME, WHEELSET");
    VehicleBody b;
    b.name = t.name;
    b.kind = static_cast<BodyKind>(t.kind);
    b.mass = t.mass;
    b.inertia = array_of(t.inertia);
    b.products_of_inertia = array_of(t.products_of_inertia);
    b.position = array_of(t.position);
    b.external_force = array_of(t.external_force);
    v.bodies.push_back(b);
  }
  for (const vehicle_element_t& t : m.vehicle_elements) {
    const std::string where = "vehicle: element '" + t.name + "': ";
    if (t.kind < vehicle_element_t::SPRING_DAMPER || t.kind > vehicle_element_t::NONLINEAR_DAMPER)
      throw std::invalid_argument(where + "kind: " + std::to_string(t.kind) +
                                  " is none of SPRING_DAMPER, TORSIONAL_SPRING, BUMP_STOP, NONLINEAR_DAMPER");
    if (t.direction < 0 || t.direction > 2)
      throw std::invalid_argument(where + "direction: " + std::to_string(t.direction) + " is none of 0 (x), 1 (y), 2 (z)");
    check_count(("element '" + t.name + "': num_curve_points").c_str(), t.num_curve_points, t.curve_velocity.size(),
                kMaxDamperCurvePoints);
    if (t.curve_force.size() != t.curve_velocity.size())
      throw std::invalid_argument(where + "curve: " + std::to_string(t.curve_force.size()) + " forces for " +
                                  std::to_string(t.curve_velocity.size()) + " velocities");
    VehicleElement e;
    e.name = t.name;
    e.kind = static_cast<ElementKind>(t.kind);
    e.bodies = {t.body_a, t.body_b};
    e.attachments = {array_of(t.attachment_a), array_of(t.attachment_b)};
    e.stiffness = array_of(t.stiffness);
    e.damping = array_of(t.damping);
    e.yaw_stiffness = t.yaw_stiffness;
    e.roll_stiffness = t.roll_stiffness;
    e.yaw_damping = t.yaw_damping;
    e.roll_damping = t.roll_damping;
    e.direction = t.direction;
    e.clearance = t.clearance;
    e.stop_stiffness = t.stop_stiffness;
    for (std::size_t k = 0; k < t.curve_velocity.size(); ++k) e.curve.emplace_back(t.curve_velocity[k], t.curve_force[k]);
    v.elements.push_back(e);
  }
  try {
    validate(v);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("vehicle: ") + e.what());
  }
  return v;
}

}  // namespace wrc::protocol
