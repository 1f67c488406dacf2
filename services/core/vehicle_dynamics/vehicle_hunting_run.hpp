// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle's hunting runs (docs/vehicle.md, "Hunting of a vehicle"): the runs of the bifurcation
/// diagram (core/dynamics/hunting_continuation.hpp) for a vehicle of several bodies on straight
/// track, judged by its leading wheelset's lateral motion as the lone wheelset's are by its own.

#include <memory>

#include "core/dynamics/hunting_continuation.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

namespace wrc {

/// A HuntingRunner of base's vehicle (its track and irregularities ignored: straight track; the
/// integrator's tolerances and step limits are base's, the end time and output period the
/// settings') at the speed asked, with contact and r0 nominal_radius [m]. A start that is the end
/// (HuntingRun::end) of one of this runner's own runs continues that run's whole vehicle (every
/// body's displacement and rates, the spins: the ramp-down and its bisection); any other start
/// holds the first wheelset at its y and yaw with the vehicle at rest about it and releases it (its
/// rates must be 0). The run is judged by the first wheelset's y (follow_hunting); its end is that
/// wheelset's lateral state.
/// @throws std::invalid_argument for invalid settings or a vehicle the equations cannot take.
HuntingRunner vehicle_hunting_runner(VehicleRunSpec base, std::shared_ptr<ContactEvaluator> contact,
                                     double nominal_radius, HuntingSettings settings);

}  // namespace wrc
