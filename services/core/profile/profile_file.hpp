// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Reads a profile file of any supported format, chosen by the file name extension.

#include <string>

#include "core/profile/profile.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {

/// Reads a profile file: ".prw"/".prr" (any case) SIMPACK (simpack_reader.hpp), ".ban" MiniProf
/// (miniprof_reader.hpp), anything else plain text/CSV (text_profile_reader.hpp). Point files
/// become SplineProfile curves (spline_profile.hpp).
/// @throws ProfileError naming file, line and reason.
ProfilePtr read_profile_file(const std::string& path, ProfileSide side,
                             const ProfileFileOptions& options = {});

}  // namespace wrc
