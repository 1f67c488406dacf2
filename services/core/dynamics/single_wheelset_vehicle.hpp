// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle file of one wheelset tied to the track (parameters/vehicles/single-wheelset.json) as
/// the wheelset run's parameters: its mass, inertias and loads, and its two axle boxes as the
/// primary suspension of WheelsetParameters (docs/vehicle.md, "Running a vehicle file"). This is
/// how `wrc run --vehicle FILE` runs such a file on the lone wheelset's equations; a vehicle of
/// more bodies runs on the vehicle's (core/vehicle_dynamics/), and is refused here, naming what it
/// has. apply_wheelset_body() is the one mapping of a wheelset body to the wheelset equations'
/// parameters, for both.

#include "core/dynamics/wheelset_parameters.hpp"
#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

/// Sets p's mass, roll, spin and yaw inertia [kg, kg m^2] and lateral and vertical load [N] from
/// wheelset body b (its external force; the vertical load is -F_z, as the wheelset equations'
/// load). The rest of p stays. What the wheelset equations take of one wheelset body, alone or in
/// a vehicle: principal axes along the track (no products of inertia), its centre of gravity on
/// the centre line (position y = 0), no longitudinal external force.
/// @throws std::invalid_argument "body 'NAME': key: value [unit]; reason" for anything else.
void apply_wheelset_body(const VehicleBody& b, WheelsetParameters& p);

/// Sets p's mass, roll, spin and yaw inertia, lateral and vertical load and suspension from the
/// vehicle's one wheelset (the rest of p, speed, material, gravity, stays). What the wheelset
/// equations take: one body, a wheelset, with principal axes along the track (no products of
/// inertia), its centre of gravity on the centre line (position x = y = 0), no longitudinal
/// external force; no element, or two spring_dampers to the track at the axle boxes (0, +-b, 0)
/// of the wheelset (b > 0), mirror images of each other with equal stiffness and damping, each
/// unstretched in the nominal position (its track point is the body's position plus its wheelset
/// point; places within 1e-9 m count as one). The nominal height is the centred wheelset's in contact, as for the run parameters.
/// @throws std::invalid_argument "vehicle 'NAME': body or element 'X': key: reason" for anything else.
void apply_single_wheelset(const VehicleDescription& vehicle, WheelsetParameters& p);

}  // namespace wrc
