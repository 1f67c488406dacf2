// SPDX-License-Identifier: Apache-2.0
#pragma once
// `wrc stability --vehicle FILE` for a vehicle of several bodies: its linear stability on straight
// track (core/vehicle_dynamics/vehicle_linear_stability.hpp, docs/vehicle.md "Linear stability"),
// in-process with the chosen contact model; the table, the critical speed, the CSV and the plot.

#include <string>
#include <vector>

#include "cli/options.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/vehicle/vehicle_description.hpp"
#include "core/vehicle_dynamics/vehicle_linear_stability.hpp"

namespace wrc::cli {

/// The vehicle's linear critical speed found in a scan, in the lone wheelset's terms (speed,
/// frequency and kind of the mode crossing).
CriticalSpeed critical_speed_from(const VehicleCriticalSpeed& found);

/// Prints the least damped mode per speed and the critical speed, writes csv and picture.
/// @throws UsageError for a parameter option that belongs to the vehicle file (masses, loads,
///         the lone wheelset's suspension).
int run_vehicle_stability(const Options& o, const VehicleDescription& vehicle, const std::string& vehicle_path,
                          const std::string& model, const std::vector<double>& speeds, const std::string& csv,
                          const std::string& picture);

}  // namespace wrc::cli
