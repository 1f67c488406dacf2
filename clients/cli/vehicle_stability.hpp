// SPDX-License-Identifier: Apache-2.0
#pragma once
// `wrc stability --vehicle FILE` for a vehicle of several bodies: its linear stability on straight
// track (core/vehicle_dynamics/vehicle_linear_stability.hpp, docs/vehicle.md "Linear stability"),
// in-process with the chosen contact model; the table, the critical speed, the CSV and the plot.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/vehicle/vehicle_description.hpp"
#include "core/vehicle_dynamics/vehicle_linear_stability.hpp"

namespace wrc::cli {

/// The linear critical speed over speeds [m/s] (ascending) with contact and r0 [m]: of vehicle
/// when given (the common run values from spec), else of spec's lone wheelset with its parameters
/// as they are; in the lone wheelset's terms (speed, frequency and kind of the mode crossing).
CriticalSpeed linear_critical_speed(const RunSpec& spec, const std::optional<VehicleDescription>& vehicle,
                                    std::shared_ptr<ContactEvaluator> contact, double r0,
                                    const std::vector<double>& speeds);

/// Prints the least damped mode per speed and the critical speed, writes csv and picture.
/// @throws UsageError for a parameter option that belongs to the vehicle file (masses, loads,
///         the lone wheelset's suspension).
int run_vehicle_stability(const Options& o, const VehicleDescription& vehicle, const std::string& vehicle_path,
                          const std::string& model, const std::vector<double>& speeds, const std::string& csv,
                          const std::string& picture);

}  // namespace wrc::cli
