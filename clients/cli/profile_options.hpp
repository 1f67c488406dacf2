// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Profile and track options shared by the geometry commands (geometry, points, conicity, query).

#include <vector>

#include "cli/options.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "options/geometry_options.hpp"

namespace wrc::cli {

/// The profile and track option specs, the table wrc-contactd uses too (options/geometry_options.hpp).
inline std::vector<OptionSpec> profile_option_specs() { return geometry_option_specs(); }

using wrc::geometry_spec_from_options;

/// Builds the wheelset geometry of geometry_spec_from_options(options).
WheelsetGeometry geometry_from_options(const Options& options);

/// The specs of the options pose_from_options() reads: --y, --roll, --yaw.
std::vector<OptionSpec> pose_option_specs();

/// The wheelset pose from --y (required) [m], --roll and --yaw (default 0) [rad], with height z [m].
WheelsetPose pose_from_options(const Options& options, double z);

/// The spec of the option side_from_options() reads: --wheel-side.
OptionSpec side_option_spec();

/// The wheel named by --wheel-side: left (default) or right.
WheelSide side_from_options(const Options& options);

}  // namespace wrc::cli
