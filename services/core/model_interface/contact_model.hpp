// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one interface every contact model implements (Hertzian one-point, interpolated Hertzian,
/// Hertzian multi-point, Arnold's spline model): the same query in, the same result out, so that
/// the models are interchangeable in-process and behind wrc-contactd on the bus.

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/contact/creep_forces.hpp"
#include "core/contact/fastsim.hpp"
#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/model_interface/rail_offset.hpp"

namespace wrc {

/// How normal forces are found.
enum class ContactFormulation {
  kRigid,    ///< the caller gives the normal load per wheel (rigid contact, constraint forces)
  kElastic,  ///< normal forces follow from the penetration of the undeformed surfaces (Hertz)
};

/// Elastic and friction data of wheel and rail (identical materials).
struct ContactMaterial {
  double shear_modulus = 8.2e10;  ///< G [Pa]
  double poisson_ratio = 0.28;    ///< nu [-]
  double friction = 0.3;          ///< Coulomb friction coefficient mu [-]
};

/// One configuration to evaluate, with the velocities the creepages need.
struct ContactQuery {
  WheelsetPose pose;       ///< y [m], z = height of the wheelset centre above the top-of-rail plane [m], roll, yaw [rad]
  double y_dot = 0;        ///< lateral velocity [m/s]
  double z_dot = 0;        ///< vertical velocity [m/s]
  double roll_dot = 0;     ///< roll rate [rad/s]
  double yaw_dot = 0;      ///< yaw rate [rad/s]
  double spin_rate = 0;    ///< angular velocity about the axle [rad/s]; forward rolling: +speed / r0
  double speed = 30.0;     ///< forward speed V [m/s] (> 0)
  std::array<double, 2> normal_load{0.0, 0.0};  ///< kRigid: normal load on the left [0] and right [1] wheel [N]
  ContactFormulation formulation = ContactFormulation::kRigid;
  ContactMaterial material;
  int fastsim_elements = kDefaultFastsimGrid;  ///< FASTSIM elements per strip (rolling direction)
  int fastsim_strips = kDefaultFastsimGrid;    ///< FASTSIM strips (lateral)
  /// The contact-point branch to follow on the left [0] and right [1] wheel: the wheel profile
  /// coordinate s of the point the caller is on (its last accepted step, or the switch_s_wheel of
  /// the event that put it there) [m]. NaN: the model's own choice (the lowest point). Models
  /// whose contact point cannot jump ignore it (see WheelConstraint::switch_function).
  std::array<double, 2> tracked_s_wheel{std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::quiet_NaN()};
  /// Rigid two-point contact of the left [0] and right [1] wheel: the wheel profile coordinate s
  /// of a second contact point the caller holds in contact besides tracked_s_wheel [m] (the
  /// sliding mode where two minima of the distance are equally low and the one-point contact
  /// point would chatter between them, docs/dynamics.md); NaN: one point. Only kRigid, and only
  /// models whose contact point jumps (onepoint) use it; the others ignore it and answer no
  /// ContactResult::second_wheels.
  std::array<double, 2> second_tracked_s_wheel{std::numeric_limits<double>::quiet_NaN(),
                                               std::numeric_limits<double>::quiet_NaN()};
  /// kRigid: normal load on the second point of a wheel in two-point contact [N] (>= 0).
  std::array<double, 2> second_normal_load{0.0, 0.0};
  /// Where the left [0] and right [1] rail lie at the wheelset, moved from their nominal place by
  /// the track's irregularities (rail_offset.hpp; all 0: the nominal track). Each wheel is
  /// evaluated against its own rail (RailFrame); the result stays in the track frame.
  std::array<RailOffset, 2> rail_offsets{};
  /// In a batch: 0, or k >= 1: this configuration follows the points answered for configuration
  /// k - 1 of the same batch (an earlier one): before it is evaluated, its tracked_s_wheel (and
  /// second_tracked_s_wheel where set) become that answer's points (apply_follows(),
  /// core/model_interface/followed_points.hpp) [-].
  int follows = 0;
};

/// switch_function of a model whose contact point never jumps [m].
constexpr double kNoSwitch = 1.0;

/// The contact constraint of one wheel, present for both wheels whatever their load (lifted and
/// unloaded wheels too): what a rigid-contact integrator needs (the gap, its gradient, the event
/// function of the contact point's jumps).
struct WheelConstraint {
  /// Vertical distance of wheel and rail at the model's contact point at the query pose [m]
  /// (< 0: the undeformed surfaces overlap). Rigid contact is gap = 0.
  double gap = 0;
  /// d gap / d(y, z, roll, yaw) [-, -, m/rad, m/rad]. The normal force N on the wheel along its
  /// contact normal n acts on the coordinates as the generalised force N n_z gap_gradient.
  Eigen::Vector4d gap_gradient{0, 1, 0, 0};
  /// d gap / dt at a fixed pose, from the rail moving under the travelling wheelset (the query's
  /// rail offset rates) [m/s]: d gap / dt = gap_gradient . (y, z, roll, yaw)' + gap_rate. 0 on a
  /// nominal track.
  double gap_rate = 0;
  double normal_z = 1;  ///< vertical component of the unit contact normal n [-] (see gap_gradient)
  double s_wheel = 0;   ///< wheel profile coordinate of the contact point the model used [m]
  double contact_angle = 0;  ///< contact angle there [rad] (ContactPoint::contact_angle)
  /// Event function of the model's branch [m]: > 0 while the contact point the model follows is
  /// the one it should be on, continuous in the pose for that branch, decreasing through 0 where
  /// the contact point jumps (another potential point becomes the lowest, or the followed one
  /// ceases to exist) or the model changes regime (spline model: flange contact). kNoSwitch for a
  /// model without jumps.
  double switch_function = kNoSwitch;
  /// The tracked_s_wheel to query with after the switch_function's root [m] (NaN: none).
  double switch_s_wheel = std::numeric_limits<double>::quiet_NaN();
};

/// One contact patch: the geometry at its centre, the Hertz ellipse, forces and creepages.
struct ContactPatch {
  ContactPoint point;       ///< position, normal, angle, radius, curvatures (see contact_point.hpp)
  double a = 0;             ///< semi-axis in the rolling direction [m]
  double b = 0;             ///< semi-axis in the lateral direction [m]
  double penetration = 0;   ///< approach of the surfaces along the normal [m] (kRigid: 0)
  double normal_force = 0;  ///< [N], >= 0
  Creepages creepages;      ///< longitudinal, lateral [-], spin [1/m]
  CreepForces forces;       ///< fx, fy [N] and mz [N m] on the wheel, contact frame
  /// The lateral relative curvature B was raised to the conformal-contact floor (B <= floor * A at
  /// the point, see ContactModelOptions::lateral_curvature_floor): Hertz does not hold there.
  bool lateral_curvature_floored = false;
};

/// Result of one configuration: every patch (left wheel first, then right), both wheels'
/// constraints and the resultant.
struct ContactResult {
  std::vector<ContactPatch> patches;
  std::array<WheelConstraint, 2> wheels;  ///< left [0] and right [1] wheel, always both
  /// The second point's constraint of a wheel in rigid two-point contact, where the query asked
  /// for one (ContactQuery::second_tracked_s_wheel) and the model supports it; its
  /// switch_function is 1 (the pair's events are in wheels[i]).
  std::array<std::optional<WheelConstraint>, 2> second_wheels;
  Eigen::Vector3d force{0, 0, 0};   ///< resultant of normal and creep forces on the wheelset, track frame [N]
  Eigen::Vector3d moment{0, 0, 0};  ///< resultant moment about the wheelset centre, track frame [N m]
  Eigen::Vector3d creep_force{0, 0, 0};   ///< resultant of the creep forces alone, track frame [N]
  Eigen::Vector3d creep_moment{0, 0, 0};  ///< their moment (and the spin moments) about the centre [N m]
};

/// The configuration cannot be in contact as asked: a wheel far off its rail, beyond flange
/// climb, or no penetration anywhere in the elastic formulation with a positive load. The message
/// names the configuration.
struct ContactConfigurationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The configuration lies outside the range a model was built for (an interpolation table's or a
/// spline model's box): not a derailment, the model cannot answer there. The message names the
/// coordinate and the range.
struct OutsideModelError : ContactConfigurationError {
  using ContactConfigurationError::ContactConfigurationError;
};

/// A contact model. evaluate() is const and thread-compatible.
class ContactModel {
 public:
  virtual ~ContactModel() = default;
  /// "onepoint", "interp", "multipoint" or "spline".
  virtual std::string name() const = 0;
  /// Throws std::invalid_argument naming the value for a malformed query (NaN, negative load,
  /// speed <= 0, bad material or grid), ContactConfigurationError for an impossible configuration.
  virtual ContactResult evaluate(const ContactQuery& query) const = 0;
  /// The wheel/rail/track geometry the model was built for.
  virtual const WheelsetGeometry& geometry() const = 0;
};

}  // namespace wrc
