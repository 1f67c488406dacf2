// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Consistent values to (re)start the integration from: the rigid state projected onto its
/// contact constraints (positions, then velocities), the elastic state settled on its contact, and
/// the derivatives (rigid: also the normal forces) consistent with a state. WheelsetSimulation
/// uses them at its start, at every restart after an event and at every model swap.

#include <array>
#include <functional>
#include <vector>

#include "core/dynamics/followed_branches.hpp"
#include "core/dynamics/wheelset_equations.hpp"
#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// [m] the elastic settling starts this far below the rigid contact: the static Hertz approach of
/// a typical wheel load (about 0.1 mm for the benchmark's 77 kN); a Hertz spring at zero approach
/// has no stiffness to start Newton's method from.
inline constexpr double kElasticStartDepth = 1e-4;

/// A constraint the rigid formulation holds: each wheel's point, and the second point of a wheel
/// in two-point contact, with the index of its normal force in the state.
struct ActiveConstraint {
  int wheel;    ///< 0 left, 1 right
  bool second;  ///< the second point of a two-point contact
  int normal;   ///< index of its normal force in the state (kUnknownNormalLeft, ...)
  const WheelConstraint& of(const ContactResult& c) const;
};

/// The active constraints of the branches: both wheels' points, then every second point.
std::vector<ActiveConstraint> active_constraints(const FollowedBranches& branches);

/// What the initialisation works on: the run's equations, formulation and followed branches, and
/// its contact, which the run evaluates, caches and counts.
struct InitialisationContext {
  const WheelsetEquations& equations;
  ContactFormulation formulation;
  const FollowedBranches& branches;
  /// The contact at the state y (unknown_count(formulation, branches.any_two_point()) values);
  /// the reference is valid until the next call.
  std::function<const ContactResult&(const double* y)> contact_at;
  /// The contact of a batch of queries in one evaluation, one result per query in order.
  std::function<std::vector<ContactResult>(const std::vector<ContactQuery>&)> evaluate;
  /// The contact at the state y with the rails as they lie dt [s] later under the travelling
  /// wheelset (irregularities); empty when the rails do not move (the constraints do not depend on
  /// time).
  std::function<ContactResult(const double* y, double dt)> contact_later;
};

/// Rigid: moves the pose of y onto the active constraints (every |gap| below 1e-13 m): in
/// two-point contact the smallest correction in the mass metric (Gauss-Newton), then height and
/// roll by Newton's method on both wheels' gaps. @throws std::runtime_error when it does not
/// converge (the message names y and yaw).
void project_positions(const InitialisationContext& context, std::vector<double>& y);

/// Rigid: removes the velocity of y along the active constraints' normals (an inelastic impact in
/// the mass metric), so that every gap rate is 0.
void project_velocities(const InitialisationContext& context, std::vector<double>& y);

/// Elastic: the height and roll of y at which the contact forces give the vertical
/// [m/s^2] and roll [rad/s^2] accelerations asked for (at rest: 0), by Newton's method with a
/// finite-difference Jacobian and step halving. @throws std::runtime_error when none is found.
void settle_elastic(const InitialisationContext& context, std::vector<double>& y, double z_acceleration,
                    double roll_acceleration);

/// The state y of formulation `from` made one of the context's formulation (a model swap): to
/// rigid, its normal forces from normal_forces [N] (from elastic; from rigid y keeps its own), then
/// positions and velocities projected onto the constraints; rigid to elastic, settled on the
/// elastic contact at the vertical and roll accelerations z_acceleration [m/s^2] and
/// roll_acceleration [rad/s^2] it had. @throws what the projections and settle_elastic throw.
void adapt_to_formulation(const InitialisationContext& context, ContactFormulation from, std::vector<double>& y,
                          const std::array<double, 2>& normal_forces, double z_acceleration,
                          double roll_acceleration);

/// y' consistent with y; rigid: also the normal forces in y (from the constraints on the
/// acceleration level), the multipliers set to 0.
void consistent_derivatives(const InitialisationContext& context, std::vector<double>& y, std::vector<double>& yp);

}  // namespace wrc
