// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The track parameters, declared once: per member of TrackParameters its key (the geometry
/// key's and track_t's name; track_t calls the inclination rail_inclination), command-line option
/// (--gauge, --gauge-depth, --flange-back, --taping-line-offset, --inclination, --r0), unit,
/// description and valid range; the default is TrackParameters{}'s. TrackParameters::validate,
/// the profile and track options (options/geometry_options.hpp), the track_t codec, the geometry
/// key's text and geometry_arguments are generated from it.

#include <vector>

#include "core/geometry/track.hpp"
#include "core/numerics/parameter_table.hpp"

namespace wrc {

/// Every track parameter, in the order of the geometry key's text.
const std::vector<Parameter<TrackParameters>>& track_parameter_table();

}  // namespace wrc
