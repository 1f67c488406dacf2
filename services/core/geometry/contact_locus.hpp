// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The curve C of the paper (section 3): wheel-surface points whose normal lies in a rail
/// cross-section plane, and the vertical distance to the rail along it.

#include <Eigen/Core>

#include "core/geometry/placed_rail.hpp"
#include "core/geometry/track.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/profile/profile.hpp"

namespace wrc {

/// One point of the curve C, parametrised by the wheel profile coordinate s.
struct LocusPoint {
  bool over_rail = false;    ///< the point lies above the rail surface's lateral extent
  double s = 0;              ///< wheel profile coordinate [m]
  double sin_theta = 0;      ///< sine of the angular position theta on the wheel (from its lowest point, > 0 towards -x_body)
  double cos_theta = 1;      ///< cosine of theta
  double radius = 0;         ///< wheel radius R(s) = r0 + F(s) [m]
  Eigen::Vector3d wheel{0, 0, 0};    ///< the wheel point in the track frame [m]
  Eigen::Vector3d tangent{0, 0, 0};  ///< dC/ds in the track frame [-]
  RailSample rail;           ///< rail surface below the wheel point
  double distance = 0;       ///< vertical distance wheel point minus rail surface [m]
  double distance_slope = 0; ///< d(distance)/ds [-]
};

/// The curve C of one wheel for one wheelset pose. Evaluation is cheap (one wheel-profile and one
/// rail-profile evaluation plus a few trigonometric functions) and allocation-free.
class ContactLocus {
 public:
  /// wheel, rail and wheel_envelope (bounds of |F'|, |F''| of the wheel profile; optional) must
  /// outlive the locus.
  ContactLocus(const Profile& wheel, const PlacedRail& rail, const TrackParameters& track,
               WheelSide side, const WheelsetPose& pose, const SlopeEnvelope* wheel_envelope = nullptr);

  /// An upper bound of |d2(distance)/ds2| over [s0, s1] [1/m], from the profile envelopes; 0 when
  /// no wheel envelope was given (callers then sample uniformly).
  double distance_curvature_bound(double s0, double s1) const;

  /// The point of C at wheel profile coordinate s [m] (clamped to the wheel profile's domain).
  LocusPoint at(double s) const;

  /// d(distance)/ds at s [-]; NaN when the point is not over the rail.
  double distance_slope(double s) const;

  /// Distance [m] and d(distance)/ds [-] at s (lean path of at()); both NaN off the rail.
  void distance_and_slope(double s, double& distance, double& slope) const;

  /// Track-frame lateral position of the locus point at s [m].
  double lateral_at(double s) const;

  /// The wheel profile coordinate s [m] whose locus point lies at track lateral position y [m]
  /// (secant iteration; used to map rail breakpoints onto the wheel).
  double s_at_lateral(double y) const;

  /// Range of s [m] whose points can lie over the rail (wheel domain intersected with the rail's
  /// lateral extent, with a margin for roll and yaw).
  double s_lower() const { return s_lower_; }
  double s_upper() const { return s_upper_; }

  /// Unit outward normal of the wheel surface at a locus point (pointing from the wheel towards
  /// the rail), in the track frame.
  Eigen::Vector3d wheel_normal(const LocusPoint& p, double slope) const;

  const Eigen::Matrix3d& rotation() const { return rotation_; }
  WheelSide side() const { return side_; }
  const WheelsetPose& pose() const { return pose_; }
  const Profile& wheel_profile() const { return wheel_; }
  const PlacedRail& rail() const { return rail_; }
  double nominal_radius() const { return r0_; }

 private:
  // Track-frame lateral position and height of a locus point and their derivatives along s.
  struct LeanPoint {
    double y, z, dy, dz;
  };
  LeanPoint lean_at(double s) const;

  const Profile& wheel_;
  const PlacedRail& rail_;
  const SlopeEnvelope* wheel_envelope_;
  WheelSide side_;
  WheelsetPose pose_;
  double sigma_;
  double taping_;
  double r0_;
  Eigen::Matrix3d rotation_;
  double rho_, beta_, a12_, cos_beta_, sin_beta_, abs_sin_roll_, abs_sin_yaw_;
  double s_lower_, s_upper_;
};

}  // namespace wrc
