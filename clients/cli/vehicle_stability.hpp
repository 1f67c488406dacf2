// SPDX-License-Identifier: Apache-2.0
#pragma once
// `wrc stability --vehicle FILE` for a vehicle of several bodies: its linear stability on straight
// track (core/vehicle_dynamics/vehicle_linear_stability.hpp, docs/vehicle.md "Linear stability"),
// in-process with the chosen contact model; the table, the critical speed, the CSV and the plot.

#include <string>
#include <vector>

#include "cli/options.hpp"
#include "core/vehicle/vehicle_description.hpp"

namespace wrc::cli {

/// Prints the least damped mode per speed and the critical speed, writes csv and picture.
/// @throws UsageError for a parameter option that belongs to the vehicle file (masses, loads,
///         the lone wheelset's suspension).
int run_vehicle_stability(const Options& o, const VehicleDescription& vehicle, const std::string& vehicle_path,
                          const std::string& model, const std::vector<double>& speeds, const std::string& csv,
                          const std::string& picture);

}  // namespace wrc::cli
