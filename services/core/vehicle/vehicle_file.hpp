// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The vehicle file (docs/vehicle.md; the vehicle equations that run it are still to come): one JSON
/// object, comments allowed,
/// `name`, `bodies` and `elements`. Each body and element is an object of the keys its kind has
/// (VehicleBody, VehicleElement in core/vehicle/vehicle_description.hpp): an unknown key, a
/// missing one, a key given twice, a wrong type or an invalid value is refused as
/// "<file>: body 'NAME': KEY: reason" (or element), before anything runs.

#include <string>

#include "core/vehicle/vehicle_description.hpp"

namespace wrc {

/// The vehicle of a file's JSON text. @param source the name for messages (the path).
/// @throws std::invalid_argument naming source, the body or element and the key.
VehicleDescription parse_vehicle(const std::string& json_text, const std::string& source);

/// Reads path (a regular file of at most 1 MB) and parses it.
/// @throws std::invalid_argument (content), std::runtime_error (the file cannot be read).
VehicleDescription read_vehicle_file(const std::string& path);

}  // namespace wrc
