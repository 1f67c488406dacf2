#pragma once
/// @file
/// The one interface every contact model implements (Hertzian one-point, interpolated Hertzian,
/// Hertzian multi-point, Arnold's spline model): the same query in, the same result out, so that
/// the models are interchangeable in-process and behind wrc-contactd on the bus.

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/contact/creep_forces.hpp"
#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/geometry/wheelset_pose.hpp"

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
  int fastsim_elements = 20;  ///< FASTSIM elements per strip (rolling direction)
  int fastsim_strips = 20;    ///< FASTSIM strips (lateral)
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

/// Result of one configuration: every patch (left wheel first, then right) and the resultant.
struct ContactResult {
  std::vector<ContactPatch> patches;
  Eigen::Vector3d force{0, 0, 0};   ///< resultant of normal and creep forces on the wheelset, track frame [N]
  Eigen::Vector3d moment{0, 0, 0};  ///< resultant moment about the wheelset centre, track frame [N m]
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
