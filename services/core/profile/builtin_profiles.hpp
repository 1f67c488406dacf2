// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The built-in profiles: one list of their names, for the profile factory that builds them and
/// for the geometry key that names them instead of reading a file.

#include <array>
#include <string>

#include "core/profile/profile.hpp"

namespace wrc {

/// A profile built in under a fixed name: its side and how to build it.
struct BuiltinProfile {
  const char* name;
  ProfileSide side;
  ProfilePtr (*make)();
};

/// "S1002" (wheel): analytic S1002; "UIC60" (rail): EN 60E1 construction; "UIC60-MB" (rail): the
/// Manchester variant (R80 at 7.7 mm).
extern const std::array<BuiltinProfile, 3> kBuiltinProfiles;

/// Prefixes of the built-in profiles with one parameter: "conic:<slope [-]>" (wheel) and
/// "circle:<radius [m]>" (rail).
inline constexpr const char* kConicPrefix = "conic:";
inline constexpr const char* kCirclePrefix = "circle:";

/// The entry of kBuiltinProfiles named spec (case-sensitive), nullptr for any other spec.
const BuiltinProfile* find_builtin_profile(const std::string& spec);

}  // namespace wrc
