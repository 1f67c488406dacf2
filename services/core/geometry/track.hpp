// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Track and wheelset dimensions that place the wheel and rail profiles in the track frame.
/// Track frame: x forward along the track, y lateral positive to the left, z up; z = 0 is the
/// top-of-rail plane.

#include <cmath>
#include <string>

namespace wrc {

/// Dimensions of the track and the wheelset (defaults: standard gauge, 1:40, S1002 nominal radius).
struct TrackParameters {
  double gauge = 1.435;              ///< track gauge between the gauge faces [m]
  double gauge_depth = 0.014;        ///< depth below the top of rail where the gauge is measured [m]
  double flange_back_spacing = 1.360;///< distance between the inner faces of the two wheels [m]
  double taping_line_offset = 0.070; ///< taping line distance from the wheel's inner face [m]
  double inclination = std::atan(1.0 / 40.0); ///< rail inclination towards the track centre [rad]
  double nominal_radius = 0.46;      ///< wheel radius at the taping line, r0 [m]

  /// Lateral distance of each wheel's taping line from the wheelset centre [m]
  /// (flange-back spacing / 2 + taping-line offset: 0.75 m by default).
  double taping_half_distance() const { return 0.5 * flange_back_spacing + taping_line_offset; }

  /// Throws std::invalid_argument naming the first value that is NaN or outside its physical range.
  void validate() const;
};

/// Parses an inclination given as "1:40", "1:20", "none"/"0" or a number in radians.
/// Throws std::invalid_argument naming the text when it is not one of these.
double parse_inclination(const std::string& text);

}  // namespace wrc
