// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A profile given by points (from a file), represented by a C2 interpolating cubic spline.

#include <string>
#include <vector>

#include "core/numerics/cubic_spline.hpp"
#include "core/profile/profile.hpp"
#include "core/profile/profile_points.hpp"

namespace wrc {

/// Minimum lateral spacing of the spline knots [m] (1e-5 m = 0.01 mm).
///
/// Smoothing method: the points are thinned so that consecutive knots are at least this far apart
/// laterally (the first and last point are always kept; a point closer than this to the last kept
/// one is dropped), and an interpolating cubic spline (C2, parabolic end curvature) is laid through
/// the kept points. Why: the Manchester rail file has points 1e-6 mm apart laterally on its
/// near-vertical ends, printed to 8 digits, so the rounding of the lateral coordinate (5e-7 mm) is
/// comparable to the spacing and the local slope (up to 54) would be pure noise; 0.01 mm spacing
/// bounds the slope noise to about 5e-5 * slope. The S1002 file (0.03 mm minimum spacing) keeps all
/// its points. Deviation: the curve passes through every kept point exactly; the tests measure the
/// distance from the dropped points and from the analytic profiles between the points.
constexpr double kSplineMinKnotSpacing = 1e-5;

/// A profile from points: the spline of the thinned points, domain = first to last point.
class SplineProfile final : public Profile {
 public:
  /// @param points validated points (see validate_profile_points), increasing lateral [m]
  /// @param side wheel or rail
  /// @param name e.g. "file MBench_S1002_v3.prw"
  /// @param built_in_cant rail inclination contained in the data [rad] (0 for wheels)
  /// @param min_spacing minimum lateral knot spacing [m] (see kSplineMinKnotSpacing)
  SplineProfile(const ProfilePoints& points, ProfileSide side, std::string name,
                double built_in_cant, double min_spacing = kSplineMinKnotSpacing);

  /// Height [m], slope [-], second derivative [1/m] of the spline.
  ProfileSample evaluate(double s) const override;
  /// First point's lateral coordinate [m].
  double lower() const override;
  /// Last point's lateral coordinate [m].
  double upper() const override;
  /// Empty: spline knots are not breakpoints (the curve is C2 across them).
  std::vector<double> breakpoints() const override { return {}; }
  /// Wheel or rail, as constructed.
  ProfileSide side() const override { return side_; }
  /// As constructed.
  std::string name() const override { return name_; }
  /// As constructed [rad].
  double built_in_cant() const override { return built_in_cant_; }

  /// The original (unthinned) points [m], for deviation checks.
  const ProfilePoints& points() const { return points_; }
  /// Number of spline knots kept after thinning.
  std::size_t knot_count() const { return spline_.knots().size(); }

 private:
  ProfilePoints points_;
  CubicSpline spline_;
  ProfileSide side_;
  std::string name_;
  double built_in_cant_;
};

}  // namespace wrc
