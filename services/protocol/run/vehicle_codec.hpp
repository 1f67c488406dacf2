// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle (core/vehicle/vehicle_description.hpp) <-> the vehicle fields of run_command_t
/// (vehicle_name, vehicle_bodies, vehicle_elements). No transport here.

#include <cstddef>
#include <optional>

#include "core/vehicle/vehicle_description.hpp"
#include "wrc/run_command_t.hpp"

namespace wrc::protocol {

/// Most bodies, elements and damper-curve points a run's vehicle may have.
inline constexpr std::size_t kMaxVehicleBodies = 64;
inline constexpr std::size_t kMaxVehicleElements = 256;
inline constexpr std::size_t kMaxDamperCurvePoints = 64;

/// Writes vehicle into m's vehicle fields (none: no bodies, the lone wheelset of m's parameters).
/// @throws std::invalid_argument when the vehicle has more bodies, elements or curve points than
///         the message takes.
void to_vehicle_fields(const std::optional<VehicleDescription>& vehicle, run_command_t& m);

/// The vehicle of m's vehicle fields, or none without bodies.
/// @throws std::invalid_argument naming the field, the body or element and the value: a count that
///         does not match its list or exceeds its limit, an unknown kind or direction, and every
///         rule of validate(VehicleDescription).
std::optional<VehicleDescription> vehicle_from_fields(const run_command_t& m);

}  // namespace wrc::protocol
