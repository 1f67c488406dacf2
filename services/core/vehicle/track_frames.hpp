// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The track frames along the distance (docs/vehicle.md, "The elements' forces"): the frame at
/// distance s along the track centre line has its origin on the centre line at rail level, x along
/// the centre line's tangent, y to the left, z up, and is rolled about its x axis by the cant angle
/// (docs/conventions.md; TrackLayout, core/track/track_layout.hpp). The bodies of a vehicle sit at
/// different distances, so each has its own track frame; this file gives one frame's pose in
/// another and the frames' motion along the track.
///
/// The centre line's heading is the integral of the curvature, theta(s) = int kappa; its plan
/// position the integral of (cos theta, sin theta). The curvature and the cant angle are linear
/// between the layout's segment ends (and constant before 0 and past the end), so the heading is
/// integrated exactly and the position by 8-point Gauss-Legendre on each linear piece, cut into
/// parts of at most 20 m (error below 1e-20 m per part for radii >= 50 m; rounding gives about
/// 1e-14 m over 20 m). Left out: vertical curvature and gradient (TrackLayout has none), so every
/// frame's unrolled z axis is the same vertical.

#include <Eigen/Core>

#include "core/track/track_layout.hpp"

namespace wrc {

/// The pose of one frame in another: a point with coordinates r in the first frame has
/// coordinates rotation * r + translation in the second.
struct FramePose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< [-] columns: the first frame's axes
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   ///< [m] the first frame's origin

  /// The coordinates [m] in the second frame of the point r [m] of the first.
  Eigen::Vector3d point(const Eigen::Vector3d& r) const { return rotation * r + translation; }
  /// The second frame's pose in the first.
  FramePose inverse() const {
    FramePose p;
    p.rotation = rotation.transpose();
    p.translation = -(p.rotation * translation);
    return p;
  }
};

/// The pose of frame 2 in frame 0 from that of frame 1 in frame 0 (outer) and of frame 2 in
/// frame 1 (inner).
inline FramePose compose(const FramePose& outer, const FramePose& inner) {
  FramePose p;
  p.rotation = outer.rotation * inner.rotation;
  p.translation = outer.rotation * inner.translation + outer.translation;
  return p;
}

/// The change of the centre line's heading from s0 to s, int_s0^s kappa [rad] (> 0: turned to the
/// left); s0, s [m].
double track_heading_change(const TrackLayout& layout, double s0, double s);

/// The track frame at distance s [m] in the track frame at s0 [m]: rotation
/// Rx(cant(s0))^T Rz(theta(s) - theta(s0)) Rx(cant(s)), translation Rx(cant(s0))^T (x, y, 0) with
/// (x, y) [m] the centre line's point at s in the plan axes of s0 (x along its tangent).
FramePose track_frame_pose(const TrackLayout& layout, double s0, double s);

/// How the track frame moves as its distance s grows, per metre, in its own axes: a point fixed in
/// the frame at coordinates r moves, seen from a fixed frame and expressed in the moving frame's
/// axes, at linear + angular x r per metre of s.
struct TrackFrameTwist {
  /// [rad/m] (cant rate, kappa sin(cant), kappa cos(cant)): the heading turns about the vertical,
  /// the cant about x
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear = Eigen::Vector3d::UnitX();  ///< [-] the origin runs along x
};

/// The twist at distance s [m]. The cant rate is the layout's (core/track/track_layout.hpp), 0
/// before the start where the cant stays as at 0; at a segment end, that of the segment beginning
/// there.
TrackFrameTwist track_frame_twist(const TrackLayout& layout, double s);

}  // namespace wrc
