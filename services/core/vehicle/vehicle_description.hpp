// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A rail vehicle as bodies and the elements between them (docs/vehicle.md): car bodies, bogie
/// frames and wheelsets with their masses, inertias and centres of gravity, and the springs,
/// dampers, torsional springs, bump stops and nonlinear dampers that join two bodies or a body and
/// the track. What a vehicle file (core/vehicle/vehicle_file.hpp) holds, checked.
///
/// Frames: every body's frame is parallel to the track frame in the nominal position (x forward,
/// y to the left, z up; docs/conventions.md), its origin at the body's centre of gravity. A body's
/// position is that centre's in the vehicle frame: x along the track ahead of the vehicle's
/// reference point, y to the left of the track centre line, z above the top-of-rail plane. An
/// attachment point is given in its body's frame; on the track ("track"), in the track frame at
/// the other body's distance along the track, from the centre line at rail level.

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace wrc {

enum class BodyKind { kCarBody, kBogieFrame, kWheelset };

/// One rigid body of the vehicle.
struct VehicleBody {
  std::string name;
  BodyKind kind = BodyKind::kCarBody;
  double mass = 0;                               ///< [kg] > 0
  std::array<double, 3> inertia{};               ///< [kg m^2] I_xx, I_yy, I_zz about the centre of gravity
  std::array<double, 3> products_of_inertia{};   ///< [kg m^2] I_xy, I_xz, I_yz (0 for a symmetric body)
  std::array<double, 3> position{};              ///< [m] centre of gravity: x ahead, y left, z above rail
  /// [N] a constant force on the centre of gravity in the track frame besides gravity (the load of
  /// a body the file leaves out, e.g. a car body's weight on a bogie run alone; the benchmark's
  /// Fy and Fz on its single wheelset)
  std::array<double, 3> external_force{};
};

enum class ElementKind { kSpringDamper, kTorsionalSpring, kBumpStop, kNonlinearDamper };

/// The name an element uses for the track as one of its two bodies.
inline constexpr const char* kTrackBody = "track";

/// One element between two bodies (or a body and the track), acting between an attachment point
/// on each.
struct VehicleElement {
  std::string name;
  ElementKind kind = ElementKind::kSpringDamper;
  std::array<std::string, 2> bodies;                    ///< body names, or kTrackBody
  std::array<std::array<double, 3>, 2> attachments{};   ///< [m] the point on each body, in its frame
  // spring_damper: linear in the three directions of the track frame
  std::array<double, 3> stiffness{};  ///< [N/m] k_x, k_y, k_z, >= 0
  std::array<double, 3> damping{};    ///< [N s/m] c_x, c_y, c_z, >= 0
  // torsional_spring: the relative rotation of the two bodies about z (yaw) and x (roll)
  double yaw_stiffness = 0;   ///< [N m/rad] >= 0
  double roll_stiffness = 0;  ///< [N m/rad] >= 0
  double yaw_damping = 0;     ///< [N m s/rad] >= 0
  double roll_damping = 0;    ///< [N m s/rad] >= 0
  // bump_stop and nonlinear_damper: along one direction of the track frame
  int direction = 1;          ///< 0 x, 1 y, 2 z
  double clearance = 0;       ///< [m] bump stop: free travel either way before contact, >= 0
  double stop_stiffness = 0;  ///< [N/m] bump stop: stiffness beyond the clearance, > 0
  /// Nonlinear damper: force [N] against relative velocity [m/s], points with increasing velocity
  /// from (0, 0), forces not decreasing (a blow-off is a flatter last segment); beyond the last
  /// point the last slope goes on, and the force at -v is minus the force at v.
  std::vector<std::pair<double, double>> curve;
};

struct VehicleDescription {
  std::string name;
  std::vector<VehicleBody> bodies;
  std::vector<VehicleElement> elements;

  /// The body named body_name, or nullptr.
  const VehicleBody* body(const std::string& body_name) const;
  /// [-] wheelsets, in the order of the bodies.
  std::vector<const VehicleBody*> wheelsets() const;
};

/// Checks everything a description must satisfy, naming the first violation as
/// "body 'NAME': KEY: reason" or "element 'NAME': KEY: reason": names unique and non-empty, at
/// least one wheelset, positive masses, positive-definite inertia tensors, finite values,
/// non-negative stiffnesses and dampings, elements between two different existing bodies (or one
/// and the track), a bump stop's stiffness positive, a damper curve as VehicleElement::curve says.
/// @throws std::invalid_argument.
void validate(const VehicleDescription& vehicle);

/// The file-format names of the kinds: "car_body", "bogie_frame", "wheelset"; "spring_damper",
/// "torsional_spring", "bump_stop", "nonlinear_damper".
const char* body_kind_name(BodyKind kind);
const char* element_kind_name(ElementKind kind);

}  // namespace wrc
