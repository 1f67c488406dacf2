// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/vehicle_description.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Core>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

std::string number(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

[[noreturn]] void refuse(const char* what, const std::string& name, const std::string& key, const std::string& why) {
  throw std::invalid_argument(std::string(what) + " '" + name + "': " + key + ": " + why);
}

template <std::size_t N>
void check_finite(const char* what, const std::string& name, const std::string& key, const std::array<double, N>& v) {
  for (double x : v)
    if (!std::isfinite(x)) refuse(what, name, key, number(x) + " is not a finite number");
}

void check_not_negative(const char* what, const std::string& name, const std::string& key, double v) {
  if (!std::isfinite(v)) refuse(what, name, key, number(v) + " is not a finite number");
  if (v < 0) refuse(what, name, key, number(v) + " is negative");
}

void validate_body(const VehicleBody& b) {
  if (!std::isfinite(b.mass) || !(b.mass > 0)) refuse("body", b.name, "mass", number(b.mass) + " [kg] is not positive");
  check_finite("body", b.name, "inertia", b.inertia);
  check_finite("body", b.name, "products_of_inertia", b.products_of_inertia);
  check_finite("body", b.name, "position", b.position);
  check_finite("body", b.name, "external_force", b.external_force);
  Eigen::Matrix3d tensor;
  const auto& i = b.inertia;
  const auto& p = b.products_of_inertia;  // I_xy, I_xz, I_yz; the tensor's off-diagonal is -I_ij
  tensor << i[0], -p[0], -p[1], -p[0], i[1], -p[2], -p[1], -p[2], i[2];
  const Eigen::LLT<Eigen::Matrix3d> llt(tensor);
  const std::string given = "(I_xx, I_yy, I_zz = " + number(i[0]) + ", " + number(i[1]) + ", " + number(i[2]) +
                            " kg m^2, products " + number(p[0]) + ", " + number(p[1]) + ", " + number(p[2]) + ")";
  if (llt.info() != Eigen::Success)
    refuse("body", b.name, "inertia", "the inertia tensor " + given + " is not positive definite");
  // A rigid body's principal moments obey the triangle inequality (each at most the sum of the
  // other two: I_1 + I_2 - I_3 = 2 sum m z^2 >= 0).
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor).eigenvalues();  // ascending
  if (m[2] > (m[0] + m[1]) * (1 + 1e-12))
    refuse("body", b.name, "inertia",
           "the principal moments " + number(m[0]) + ", " + number(m[1]) + ", " + number(m[2]) + " kg m^2 of " + given +
               " break the triangle inequality (the largest exceeds the sum of the others): no rigid body has them");
}

void validate_curve(const VehicleElement& e) {
  if (e.curve.size() < 2) refuse("element", e.name, "curve", "needs at least two points, (0, 0) and one more");
  if (e.curve.front() != std::make_pair(0.0, 0.0)) refuse("element", e.name, "curve", "must start at (0, 0)");
  for (std::size_t k = 1; k < e.curve.size(); ++k) {
    const auto& [v0, f0] = e.curve[k - 1];
    const auto& [v, f] = e.curve[k];
    if (!std::isfinite(v) || !std::isfinite(f))
      refuse("element", e.name, "curve", "point " + std::to_string(k) + " is not finite");
    if (!(v > v0))
      refuse("element", e.name, "curve",
             "velocities must increase: point " + std::to_string(k) + " has " + number(v) + " m/s after " + number(v0));
    if (f < f0)
      refuse("element", e.name, "curve",
             "forces must not decrease: point " + std::to_string(k) + " has " + number(f) + " N after " + number(f0));
  }
}

void validate_element(const VehicleElement& e, const std::set<std::string>& bodies) {
  for (const std::string& body : e.bodies)
    if (body != kTrackBody && !bodies.count(body)) {
      std::string known;
      for (const std::string& b : bodies) known += b + ", ";
      refuse("element", e.name, "bodies", "'" + body + "' is no body of the vehicle (bodies: " + known + kTrackBody + ")");
    }
  if (e.bodies[0] == e.bodies[1]) refuse("element", e.name, "bodies", "joins '" + e.bodies[0] + "' to itself");
  check_finite("element", e.name, "attachments", e.attachments[0]);
  check_finite("element", e.name, "attachments", e.attachments[1]);
  switch (e.kind) {
    case ElementKind::kSpringDamper:
      for (int k = 0; k < 3; ++k) {
        check_not_negative("element", e.name, "stiffness", e.stiffness[k]);
        check_not_negative("element", e.name, "damping", e.damping[k]);
      }
      break;
    case ElementKind::kTorsionalSpring:
      check_not_negative("element", e.name, "yaw_stiffness", e.yaw_stiffness);
      check_not_negative("element", e.name, "roll_stiffness", e.roll_stiffness);
      check_not_negative("element", e.name, "yaw_damping", e.yaw_damping);
      check_not_negative("element", e.name, "roll_damping", e.roll_damping);
      break;
    case ElementKind::kBumpStop:
      check_not_negative("element", e.name, "clearance", e.clearance);
      if (!std::isfinite(e.stop_stiffness) || !(e.stop_stiffness > 0))
        refuse("element", e.name, "stiffness", number(e.stop_stiffness) + " [N/m] is not positive");
      break;
    case ElementKind::kNonlinearDamper: validate_curve(e); break;
  }
  if ((e.kind == ElementKind::kBumpStop || e.kind == ElementKind::kNonlinearDamper) &&
      (e.direction < 0 || e.direction > 2))
    refuse("element", e.name, "direction", std::to_string(e.direction) + " is none of x, y, z");
}

}  // namespace

const VehicleBody* VehicleDescription::body(const std::string& body_name) const {
  for (const VehicleBody& b : bodies)
    if (b.name == body_name) return &b;
  return nullptr;
}

std::vector<const VehicleBody*> VehicleDescription::wheelsets() const {
  std::vector<const VehicleBody*> out;
  for (const VehicleBody& b : bodies)
    if (b.kind == BodyKind::kWheelset) out.push_back(&b);
  return out;
}

void validate(const VehicleDescription& vehicle) {
  std::set<std::string> names;
  for (const VehicleBody& b : vehicle.bodies) {
    if (b.name.empty()) throw std::invalid_argument("a body has no name");
    if (b.name == kTrackBody) refuse("body", b.name, "name", "is the track's name");
    if (!names.insert(b.name).second) refuse("body", b.name, "name", "is given to two bodies");
    validate_body(b);
  }
  if (vehicle.wheelsets().empty()) throw std::invalid_argument("the vehicle has no body of kind wheelset");
  std::set<std::string> elements;
  for (const VehicleElement& e : vehicle.elements) {
    if (e.name.empty()) throw std::invalid_argument("an element has no name");
    if (!elements.insert(e.name).second) refuse("element", e.name, "name", "is given to two elements");
    validate_element(e, names);
  }
}

const char* body_kind_name(BodyKind kind) {
  switch (kind) {
    case BodyKind::kCarBody: return "car_body";
    case BodyKind::kBogieFrame: return "bogie_frame";
    case BodyKind::kWheelset: return "wheelset";
  }
  return "?";
}

const char* element_kind_name(ElementKind kind) {
  switch (kind) {
    case ElementKind::kSpringDamper: return "spring_damper";
    case ElementKind::kTorsionalSpring: return "torsional_spring";
    case ElementKind::kBumpStop: return "bump_stop";
    case ElementKind::kNonlinearDamper: return "nonlinear_damper";
  }
  return "?";
}

}  // namespace wrc
