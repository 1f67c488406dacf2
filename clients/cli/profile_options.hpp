#pragma once
/// @file
/// Profile and track options shared by the geometry commands (geometry, points, conicity, query).

#include <vector>

#include "cli/options.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc::cli {

/// Option specs: --wheel, --rail, --rail-cant, --gauge, --gauge-depth, --flange-back,
/// --taping-line-offset, --inclination, --r0.
std::vector<OptionSpec> profile_option_specs();

/// The geometry input named by parsed options (defaults: S1002 on UIC60, standard track); throws
/// UsageError naming the option for a bad value, std::invalid_argument for an invalid track.
GeometrySpec geometry_spec_from_options(const Options& options);

/// Builds the wheelset geometry of geometry_spec_from_options(options).
WheelsetGeometry geometry_from_options(const Options& options);

/// The wheelset pose from --y (required) [m], --roll and --yaw (default 0) [rad], with height z [m].
WheelsetPose pose_from_options(const Options& options, double z);

/// The wheel named by --wheel-side: left (default) or right.
WheelSide side_from_options(const Options& options);

}  // namespace wrc::cli
