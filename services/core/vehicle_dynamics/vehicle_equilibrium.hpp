// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle at rest in its track frames: the state y with F(t, y, 0) = 0 (docs/vehicle.md, "The
/// start"). Every rate is then 0 and every body's forces balance: on straight track the vehicle
/// stands on its springs and wheels, rolling at V without creep; in a curve of constant radius and
/// cant it is the steady curving state. The contact formulation is each wheelset's current one.

#include <string>
#include <vector>

#include "core/vehicle_dynamics/vehicle_dae.hpp"

namespace wrc {

/// How the equilibrium's Newton iteration ended.
struct VehicleEquilibrium {
  std::vector<double> state;  ///< y with F(t, y, 0) = 0
  int iterations = 0;         ///< Newton iterations [-]
  /// The last Newton step in the weighted RMS norm (1: each unknown moved by its tolerance) [-].
  double last_step = 0;
};

/// The weights of the convergence test: 1 / tolerance of each unknown of the layout [1/unit].
/// @param position_tolerance of displacements [m, rad]; velocity_tolerance of rates and spin
///        [m/s, rad/s]; a wheelset's scaled normal forces and multipliers take 1e-6 [-].
std::vector<double> equilibrium_weights(const VehicleDae& dae, double position_tolerance, double velocity_tolerance);

/// A wheelset held at a lateral shift and yaw: its lateral force and yaw moment balances are
/// replaced by y = lateral and yaw = yaw (a start disturbed from rest: the vehicle at rest with the
/// wheelset held there, then released).
struct HeldWheelset {
  size_t wheelset = 0;  ///< index among the vehicle's wheelsets [-]
  double lateral = 0;   ///< y [m]
  double yaw = 0;       ///< [rad]
};

/// Solves F(t, y, 0) = 0 (with the held wheelsets' rows replaced) by Newton's method from guess
/// (damped: a step is halved until the next Newton step is shorter, down to 1/64), the
/// forward-difference Jacobian of VehicleDae.
/// @throws std::runtime_error naming the time, the largest residual's body and unknown when the
///         iteration does not converge in max_iterations or the matrix is singular (a vehicle
///         not held in some direction), and what the contact throws.
VehicleEquilibrium vehicle_equilibrium(VehicleDae& dae, double t, std::vector<double> guess,
                                       const std::vector<double>& weights, const std::vector<HeldWheelset>& held = {},
                                       int max_iterations = 50);

/// The state a run or a linearisation starts from at time t [s]: every body at its nominal
/// position, each wheelset rolling at V / r0 as the guess; the equilibrium in rigid contact (a
/// Hertz spring at zero approach has no stiffness to start Newton from), then, for an elastic
/// model (own), in elastic contact from the rigid one lowered by 0.1 mm. Leaves every wheelset in
/// formulation own. The tolerances [m, rad] and [m/s, rad/s] weigh the convergence test. Where
/// Newton does not find it directly (irregular rails; a wheelset held off centre, which may put
/// another on a jump of its contact point), it is continued from the nominal rails with the held
/// wheelsets centred, raising the irregularities and the offsets together in formulation own;
/// continued = false tries Newton alone, on the rails as the equations place them now.
std::vector<double> vehicle_rest_state(VehicleDae& dae, ContactFormulation own, double t, double position_tolerance,
                                       double velocity_tolerance, const std::vector<HeldWheelset>& held = {},
                                       bool continued = true);

}  // namespace wrc
