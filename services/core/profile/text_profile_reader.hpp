// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Reader for plain two-column text/CSV profile files.

#include <string>

#include "core/profile/profile.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {

/// Reads a plain text profile: two numbers per line (separated by white space, ',' or ';').
///
/// The columns are the profile coordinates of profile.hpp directly, no mirroring:
/// wheel: s (from the taping line, positive towards the field side), F (height above the taping
/// line, positive = larger radius); rail: u (positive towards the field side), v (up).
/// Lines starting with '#' are comments; some comments are directives (any case):
/// "# units: mm" (the default) or "# units: m"; "# side: wheel" or "# side: rail" (then the file
/// may only be used as that side); "# cant: <radians>" (rail built-in cant, default 0).
/// One header line of column names (e.g. "s,F") is allowed before the first point.
///
/// @throws ProfileError with file, line and reason: unknown units, unknown side, side mismatch,
///         non-numeric or missing values, wrong column count and the point checks.
ProfilePtr read_text_profile(const std::string& path, ProfileSide side,
                             const ProfileFileOptions& options = {});

}  // namespace wrc
