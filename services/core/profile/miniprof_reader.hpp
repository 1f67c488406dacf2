// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Reader for MiniProf rail profile files (.ban).

#include <string>

#include "core/profile/profile.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {

/// Reads a MiniProf .ban rail profile.
///
/// Format: header lines "Key=Value" (ColumnDef must be "X,Y" if present), then data lines of two
/// numbers (white space or comma separated) in mm, each possibly preceded by a '"' marker (MiniProf
/// marks points that way); blank lines are skipped.
///
/// Orientation (as in MBench_UIC60_v3.ban, which is MBench_UIC60_v3.prr with y mirrored): X runs
/// towards the gauge side and Y points down, so u = -X, v = -Y (converted from mm to m).
///
/// Built-in cant: options.built_in_cant if given, else 0 (the header's Tilt fields are not
/// interpreted). The Manchester .ban file IS canted 1:40: pass atan(1/40) for it.
///
/// @param side must be ProfileSide::kRail (.ban files are rail profiles).
/// @throws ProfileError with file, line and reason for malformed input or a wheel request.
ProfilePtr read_miniprof_profile(const std::string& path, ProfileSide side,
                                 const ProfileFileOptions& options = {});

}  // namespace wrc
