// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// One exact-geometry sample of one wheel for the spline fit: the contact point on the tread
/// (flange root included), how close the next tread minimum is, and the flange clearance.

#include <array>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/spline/spline_fields.hpp"

namespace wrc {

/// The exact geometry of one wheel at one pose, split at the flange (s_split).
struct WheelSample {
  bool valid = false;      ///< the tread side (s > s_split) has a local minimum or the split point is over the rail
  /// The lowest local minimum with s > s_split (the tread contact point); without one (deep
  /// flange contact) the point of C at s_split.
  ContactPoint tread;
  /// Distance of the second-lowest tread minimum above the lowest [m] (+inf with one minimum):
  /// zero where the tread contact point jumps.
  double second_minimum_gap = 0;
  /// Lowest distance over the flange region s <= s_split (its local minima and the point s_split
  /// itself, where over the rail) minus the tread point's distance [m], capped at the cap given.
  double flange_clearance = 0;
  std::array<double, kSplineFieldCount> fields{};  ///< every fitted quantity (spline_fields.hpp)
};

/// The wheel profile coordinate that separates the flange region (s <= s_split) from the tread:
/// going from the taping line (s = 0) towards the flange in 10 um steps, the first s where the
/// profile's slope angle atan|dF/ds| exceeds flange_angle [rad]. For a profile that never gets so
/// steep (a cone), the lower end of its domain [m].
double flange_split(const Profile& wheel, double flange_angle);

/// Samples one wheel at pose (every potential point found, the tread's lowest minimum selected).
/// The Hertz fields are those of contact_shape() with lateral_curvature_floor.
/// @param s_split from flange_split() [m].  @param clearance_cap [m] > 0.
WheelSample sample_wheel(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose, double s_split,
                         double clearance_cap, double lateral_curvature_floor, const PotentialPointSearch& search);

/// Samples one branch of the wheel at pose: as sample_wheel(), but the tread point is the local
/// minimum with s > s_split nearest to s_near [m], whether or not it is the lowest (a branch
/// continued past a jump), and the clearance is that of this point. Not valid when no such
/// minimum lies within max_shift [m] of s_near (the branch has vanished).
WheelSample sample_wheel_branch(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                double s_split, double clearance_cap, double lateral_curvature_floor,
                                const PotentialPointSearch& search, double s_near, double max_shift);

}  // namespace wrc
