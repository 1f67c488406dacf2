// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/single_wheelset_vehicle.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace wrc {
namespace {

// [m] how far two places the file gives may differ and still be one: rounding of typed decimals.
constexpr double kSamePlace = 1e-9;

std::string text(const std::array<double, 3>& v) {
  std::ostringstream out;
  out << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
  return out.str();
}

[[noreturn]] void refuse(const VehicleDescription& v, const std::string& what) {
  throw std::invalid_argument("vehicle '" + v.name + "': " + what);
}

// The axle box of an element as the wheelset equations take it; returns its signed lateral place.
double axle_box(const VehicleDescription& v, const VehicleBody& wheelset, const VehicleElement& e) {
  const std::string where = "element '" + e.name + "': ";
  if (e.kind != ElementKind::kSpringDamper)
    refuse(v, where + "kind: " + element_kind_name(e.kind) +
                  " (a lone wheelset's suspension is two spring_dampers to the track)");
  const int own = e.bodies[0] == wheelset.name ? 0 : 1;
  if (e.bodies[1 - own] != kTrackBody) refuse(v, where + "bodies: the wheelset's springs go to the track");
  const std::array<double, 3>& at = e.attachments[static_cast<size_t>(own)];
  const std::array<double, 3>& on_track = e.attachments[static_cast<size_t>(1 - own)];
  if (at[0] != 0.0 || at[2] != 0.0 || at[1] == 0.0)
    refuse(v, where + "attachments: " + text(at) + " [m] on the wheelset is no axle box (0, +-b, 0) with b > 0");
  for (int k = 0; k < 3; ++k) {
    const size_t u = static_cast<size_t>(k);
    if (std::abs(on_track[u] - (wheelset.position[u] + at[u])) > kSamePlace)
      refuse(v, where + "attachments: " + text(on_track) +
                    " [m] on the track: the spring is not unstretched in the nominal position (the body's position "
                    "plus " + text(at) + ")");
  }
  return at[1];
}

}  // namespace

void apply_wheelset_body(const VehicleBody& b, WheelsetParameters& p) {
  const std::string body = "body '" + b.name + "': ";
  if (b.products_of_inertia != std::array<double, 3>{})
    throw std::invalid_argument(body + "products_of_inertia: " + text(b.products_of_inertia) +
                                " [kg m^2]; the wheelset equations take principal axes along the track");
  if (b.position[1] != 0.0)
    throw std::invalid_argument(body + "position: " + text(b.position) +
                                " [m]; a wheelset's centre is on the centre line (y = 0)");
  if (b.external_force[0] != 0.0)
    throw std::invalid_argument(body + "external_force: " + text(b.external_force) +
                                " [N]; the wheelset has no longitudinal freedom for F_x");
  p.mass = b.mass;
  p.roll_inertia = b.inertia[0];
  p.spin_inertia = b.inertia[1];
  p.yaw_inertia = b.inertia[2];
  p.lateral_force = b.external_force[1];
  p.vertical_force = -b.external_force[2];
}

void apply_single_wheelset(const VehicleDescription& vehicle, WheelsetParameters& p) {
  validate(vehicle);
  if (vehicle.bodies.size() != 1 || vehicle.bodies.front().kind != BodyKind::kWheelset)
    refuse(vehicle, "bodies: " + std::to_string(vehicle.bodies.size()) +
                        "; the lone wheelset's equations take one wheelset on the track (wrc run and wrc "
                        "stability run a vehicle of several bodies on the vehicle's, docs/vehicle.md)");
  const VehicleBody& w = vehicle.bodies.front();
  if (w.position[0] != 0.0)
    refuse(vehicle, "body '" + w.name + "': position: " + text(w.position) +
                        " [m]; a lone wheelset's centre is at x = 0 on the centre line");
  try {
    apply_wheelset_body(w, p);
  } catch (const std::invalid_argument& e) {
    refuse(vehicle, e.what());
  }
  PrimarySuspension s = PrimarySuspension::none();
  if (!vehicle.elements.empty()) {
    if (vehicle.elements.size() != 2)
      refuse(vehicle, "elements: " + std::to_string(vehicle.elements.size()) +
                          "; a lone wheelset has none or two axle boxes");
    const VehicleElement& a = vehicle.elements[0];
    const VehicleElement& b = vehicle.elements[1];
    const double ya = axle_box(vehicle, w, a), yb = axle_box(vehicle, w, b);
    if (std::abs(ya + yb) > kSamePlace) refuse(vehicle, "element '" + b.name + "': attachments: not the mirror image of '" + a.name + "'");
    if (a.stiffness != b.stiffness || a.damping != b.damping)
      refuse(vehicle, "element '" + b.name + "': stiffness, damping: not those of '" + a.name + "'");
    s.longitudinal_stiffness = a.stiffness[0];
    s.lateral_stiffness = a.stiffness[1];
    s.vertical_stiffness = a.stiffness[2];
    s.longitudinal_damping = a.damping[0];
    s.lateral_damping = a.damping[1];
    s.vertical_damping = a.damping[2];
    s.half_spacing = ya > 0.0 ? ya : yb;
  }
  p.suspension = s;
}

}  // namespace wrc
