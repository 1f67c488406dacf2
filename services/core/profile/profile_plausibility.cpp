// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/numerics/length_text.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {
namespace {

[[noreturn]] void implausible(const ProfilePoints& p, ProfileSide side, int line, const std::string& what) {
  throw ProfileError(p.source, line,
                     std::string("implausible ") + (side == ProfileSide::kWheel ? "wheel" : "rail") +
                         " profile: " + what);
}

// Height at lateral coordinate x by linear interpolation of the points (x inside their range).
double height_at(const ProfilePoints& p, double x) {
  const auto it = std::lower_bound(p.lateral.begin(), p.lateral.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - p.lateral.begin());
  if (i == 0) return p.height.front();
  const double t = (x - p.lateral[i - 1]) / (p.lateral[i] - p.lateral[i - 1]);
  return p.height[i - 1] + t * (p.height[i] - p.height[i - 1]);
}

void check_width(const ProfilePoints& p, ProfileSide side) {
  const double width = p.lateral.back() - p.lateral.front();
  if (width < kMinProfileWidth)
    implausible(p, side, 0,
                "width " + in_mm(width) + " is below " + in_mm(kMinProfileWidth) +
                    " (is the length unit off, m for mm?)");
  if (width > kMaxProfileWidth)
    implausible(p, side, 0,
                "width " + in_mm(width) + " is above " + in_mm(kMaxProfileWidth) +
                    " (is the length unit off, mm for m?)");
}

void check_height_range(const ProfilePoints& p, ProfileSide side) {
  const auto [low, high] = std::minmax_element(p.height.begin(), p.height.end());
  const double range = *high - *low;
  const double limit = side == ProfileSide::kWheel ? kMaxWheelHeightRange : kMaxRailHeightRange;
  if (range > limit)
    implausible(p, side, 0,
                "height range " + in_mm(range) + " (from " + in_mm(*low) + " to " + in_mm(*high) + ") is above " +
                    in_mm(limit));
}

void check_spikes(const ProfilePoints& p, ProfileSide side) {
  for (std::size_t i = 1; i + 1 < p.lateral.size(); ++i) {
    const double rise_before = p.height[i] - p.height[i - 1];
    const double rise_after = p.height[i] - p.height[i + 1];
    if ((rise_before > 0) != (rise_after > 0)) continue;
    const double slope_before = std::fabs(rise_before) / (p.lateral[i] - p.lateral[i - 1]);
    const double slope_after = std::fabs(rise_after) / (p.lateral[i + 1] - p.lateral[i]);
    const double height = std::min(std::fabs(rise_before), std::fabs(rise_after));
    if (height > kMinSpikeHeight && slope_before > kMinSpikeSlope && slope_after > kMinSpikeSlope)
      implausible(p, side, p.line[i],
                  "a spike of " + in_mm(height) + " " + (rise_before > 0 ? "above" : "below") +
                      " both neighbouring points (height " + in_mm(p.height[i]) + " at " + in_mm(p.lateral[i]) + ")");
  }
}

void check_wheel_shape(const ProfilePoints& p) {
  if (p.lateral.front() < 0.0 && p.lateral.back() > 0.0) {
    const double taping = height_at(p, 0.0);
    const double flange = *std::max_element(p.height.begin(), p.height.end()) - taping;
    if (flange > kMaxFlangeHeight)
      implausible(p, ProfileSide::kWheel, 0,
                  "flange height " + in_mm(flange) + " above the taping line (s = 0) is above " +
                      in_mm(kMaxFlangeHeight));
  }
  // Least-squares slope of the points.
  const double n = static_cast<double>(p.lateral.size());
  double ms = 0, mh = 0;
  for (std::size_t i = 0; i < p.lateral.size(); ++i) {
    ms += p.lateral[i] / n;
    mh += p.height[i] / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < p.lateral.size(); ++i) {
    sxy += (p.lateral[i] - ms) * (p.height[i] - mh);
    sxx += (p.lateral[i] - ms) * (p.lateral[i] - ms);
  }
  const double slope = sxy / sxx;
  if (slope > kMaxWheelMeanSlope) {
    std::ostringstream what;
    what << "mean slope " << slope << " is above " << kMaxWheelMeanSlope
         << ": the profile rises towards the field side instead of the flange (s < 0), upside down or mirrored "
            "(negative contact angles)";
    implausible(p, ProfileSide::kWheel, 0, what.str());
  }
}

void check_rail_shape(const ProfilePoints& p) {
  const double u0 = p.lateral.front(), u1 = p.lateral.back();
  const double v0 = p.height.front(), v1 = p.height.back();
  // Mean height above the chord, weighted by the lateral spacing (trapezoids).
  double area = 0;
  for (std::size_t i = 1; i < p.lateral.size(); ++i) {
    auto above = [&](std::size_t k) { return p.height[k] - (v0 + (v1 - v0) * (p.lateral[k] - u0) / (u1 - u0)); };
    area += 0.5 * (above(i) + above(i - 1)) * (p.lateral[i] - p.lateral[i - 1]);
  }
  const double mean = area / (u1 - u0);
  if (mean < -kMaxRailSagBelowChord)
    implausible(p, ProfileSide::kRail, 0,
                "it lies " + in_mm(-mean) + " below the chord between its ends on average (more than " +
                    in_mm(kMaxRailSagBelowChord) + "): the head is concave, upside down (negative contact angles)");
}

}  // namespace

void check_profile_plausibility(const ProfilePoints& points, ProfileSide side) {
  check_width(points, side);
  check_height_range(points, side);
  check_spikes(points, side);
  if (side == ProfileSide::kWheel) {
    check_wheel_shape(points);
  } else {
    check_rail_shape(points);
  }
}

}  // namespace wrc
