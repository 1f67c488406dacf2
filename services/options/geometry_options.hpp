// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The profile and track options (--wheel, --rail, --rail-cant, --gauge,
/// --gauge-depth, --flange-back, --taping-line-offset, --inclination, --r0) and its one reader:
/// the track's from the track parameter table (core/geometry/track_table.hpp). Used by the geometry commands of the `wrc` front end and by wrc-contactd, so both mean the same
/// by the same words (core/identity/geometry_key.hpp: geometry_arguments writes them).

#include <vector>

#include "core/geometry/geometry_spec.hpp"
#include "options/options.hpp"

namespace wrc {

/// Option specs: --wheel, --rail, --rail-cant, --gauge, --gauge-depth, --flange-back,
/// --taping-line-offset, --inclination, --r0.
std::vector<OptionSpec> geometry_option_specs();

/// The geometry input named by parsed options (defaults: S1002 on UIC60, standard track); throws
/// UsageError naming the option for a bad value, std::invalid_argument for an invalid track.
GeometrySpec geometry_spec_from_options(const Options& options);

}  // namespace wrc
