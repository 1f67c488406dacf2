// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The parameters of the classical wheelset model (wickens_wheelset.hpp) taken from wrc's own
/// geometry and contact at the centred steady state (docs/stability.md): conicity, rolling radius
/// and contact half distance from the exact rigid-wheelset geometry, the gravitational stiffnesses
/// as the curvature of the load's potential W z(y, yaw) (frictionless rigid contact is workless),
/// the creep coefficients from the centred patch's Hertz semi-axes and Kalker's coefficients.

#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/wickens_wheelset.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc {

/// What the classical model is built from, with the pieces it sums (for the report).
struct WickensFromModel {
  WickensWheelset model;
  double gravitational_stiffness = 0;      ///< W d2z/dy2 + 2 k_z b^2 (d roll/dy)^2 [N/m]
  double gravitational_yaw_stiffness = 0;  ///< W d2z/dyaw2 [N m/rad]
  double roll_slope = 0;                   ///< d roll / dy of the rigid wheelset [rad/m]
  double contact_angle = 0;                ///< of the left wheel at the centre [rad]
  double semi_axis_a = 0;                  ///< Hertz a (rolling) of the centred patch [m]
  double semi_axis_b = 0;                  ///< Hertz b (lateral) [m]
  double c11 = 0, c22 = 0, c23 = 0;        ///< Kalker's coefficients there [-]
};

/// The classical model of the wheelset of parameters (its suspension, masses and load) on
/// geometry, with the patch of the centred steady state (any speed: a and b do not depend on it).
/// @throws std::runtime_error when the centred state has no patch on a wheel or the geometry has
///         no rigid contact near the centre.
WickensFromModel wickens_from_model(const WheelsetGeometry& geometry, const WheelsetParameters& parameters,
                                    const CentredSteadyState& steady);

}  // namespace wrc
