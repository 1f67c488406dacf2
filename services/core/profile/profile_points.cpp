// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_points.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {

ProfilePoints validate_profile_points(ProfilePoints points) {
  const std::size_t n = points.lateral.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(points.lateral[i]) || !std::isfinite(points.height[i])) {
      throw ProfileError(points.source, points.line[i], "NaN or infinite value");
    }
    for (const double value : {points.lateral[i], points.height[i]}) {
      if (std::fabs(value) > kMaxProfileCoordinate) {
        std::ostringstream reason;
        reason << "value " << value << " m is beyond +-" << kMaxProfileCoordinate
               << " m (no wheel or rail profile reaches that far: is the length unit off?)";
        throw ProfileError(points.source, points.line[i], reason.str());
      }
    }
  }
  if (n < kMinProfilePoints) {
    std::ostringstream reason;
    reason << "too few points: " << n << " (at least " << kMinProfilePoints << " needed)";
    throw ProfileError(points.source, 0, reason.str());
  }
  const bool increasing = points.lateral[1] > points.lateral[0];
  for (std::size_t i = 1; i < n; ++i) {
    const double step = points.lateral[i] - points.lateral[i - 1];
    if (step == 0.0) {
      throw ProfileError(points.source, points.line[i],
                         "duplicate lateral coordinate (same as the previous point)");
    }
    if ((step > 0.0) != increasing) {
      throw ProfileError(points.source, points.line[i],
                         std::string("lateral coordinate not monotonic (the file runs ") +
                             (increasing ? "increasing" : "decreasing") + " before this line)");
    }
  }
  if (!increasing) {
    std::reverse(points.lateral.begin(), points.lateral.end());
    std::reverse(points.height.begin(), points.height.end());
    std::reverse(points.line.begin(), points.line.end());
  }
  return points;
}

}  // namespace wrc
