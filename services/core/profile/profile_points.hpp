// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Profile points as read from a file, already converted to profile coordinates, and their
/// validation (the checks every reader shares).

#include <string>
#include <vector>

namespace wrc {

/// Points of a profile file in profile coordinates [m] (wheel: s, F; rail: u, v; see
/// profile.hpp), in file order, each with the 1-based file line it came from.
struct ProfilePoints {
  std::string source;            ///< file path, for error messages
  std::vector<double> lateral;   ///< s or u [m]
  std::vector<double> height;    ///< F or v [m]
  std::vector<int> line;         ///< file line of each point
};

/// Fewest points a profile file may have.
constexpr std::size_t kMinProfilePoints = 4;

/// Checks the points and returns them ordered by increasing lateral coordinate: every value finite
/// and within +-kMaxProfileCoordinate (profile_limits.hpp),
/// at least kMinProfilePoints points, lateral coordinates strictly monotonic in file order (either
/// direction; a file that runs backwards is reversed).
/// @throws ProfileError naming the file and the first offending line: "NaN or infinite value", "value ... m is beyond",
///         "duplicate lateral coordinate", "lateral coordinate not monotonic", "too few points".
ProfilePoints validate_profile_points(ProfilePoints points);

}  // namespace wrc
