// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Builds a profile from a short specification string (command lines, configuration files).

#include <string>

#include "core/profile/profile.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {

/// Builds the profile named by spec for the given side:
/// - a built-in name of core/profile/builtin_profiles.hpp ("S1002", "UIC60", "UIC60-MB");
/// - "conic:<slope>" (wheel): cone F(s) = -slope*s, slope [-];
/// - "circle:<radius>" (rail): circular head, radius [m] (> 0);
/// - anything else: a profile file path (see profile_file.hpp for formats), read with options
///   (e.g. the built-in cant of a MiniProf rail file).
/// Names are case-sensitive.
/// @throws ProfileError if the spec is malformed, names a profile of the other side (e.g. "S1002"
///         asked as a rail), or the file cannot be read.
ProfilePtr make_profile(const std::string& spec, ProfileSide side,
                        const ProfileFileOptions& options = {});

}  // namespace wrc
