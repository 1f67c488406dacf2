// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a vehicle run restarts from after a contact-point switch of one of its wheelsets
/// (docs/vehicle.md, "Contact-point switches per wheelset"): the state taken apart into its bodies'
/// blocks (a switch changes one wheelset's block, and with two-point contact its size) and put
/// together again, and the derivatives y' consistent with a state: each car body's and frame's from
/// its equations (its rates and the accelerations the elements' forces give), each wheelset's as
/// the lone wheelset's restart takes them (rigid: its normal forces too).
///
/// A wheelset is joined to the other bodies by springs and dampers only, which carry no impulse:
/// the inelastic impact of a switch changes the velocities of that wheelset alone, so a wheelset's
/// projections onto its constraints (core/dynamics/consistent_initialisation.hpp) are the
/// vehicle's.

#include <functional>
#include <vector>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/vehicle_dynamics/vehicle_dae.hpp"

namespace wrc {

/// The blocks of y, one per body in the order of the vehicle's bodies (layout's sizes).
std::vector<std::vector<double>> split_by_body(const VehicleLayout& layout, const std::vector<double>& y);

/// The state of the blocks one after another.
std::vector<double> join_bodies(const std::vector<std::vector<double>>& blocks);

/// y' consistent with y at time t [s], the wheelsets' formulations and branches those of dae's
/// contact: a car body's or frame's from its residual at y' = 0 and its block of dF/dy' (its
/// rates, its mass matrix); wheelset w's by consistent_derivatives() with wheelset_initialisation(w)
/// under the elements' forces at y (rigid: it also sets the wheelset's normal forces and
/// multipliers in y).
/// @throws what the contact and the equations throw.
std::vector<double> vehicle_consistent_derivatives(
    VehicleDae& dae, double t, std::vector<double>& y,
    const std::function<InitialisationContext(size_t wheelset)>& wheelset_initialisation);

}  // namespace wrc
