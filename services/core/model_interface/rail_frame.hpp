// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The frame of one rail moved by a RailOffset: a contact model evaluates a wheel against its rail
/// there, with the rail in its nominal place, and RailFrame carries the pose and motion in and the
/// contact points, constraint and patches back into the track frame.

#include <Eigen/Core>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/rail_offset.hpp"
#include "core/model_interface/wheelset_motion.hpp"

namespace wrc {

/// Rail coordinates x_r of a track point x_t: x_t = R (x_r - p) + p + d with R the rotation
/// about x by offset.roll, p the rail's pivot (0, pivot_y, 0) and d = (0, lateral, vertical).
/// In rail coordinates the moved rail is the nominal one, so a model's geometry answers a wheel
/// there unchanged. The wheelset is axisymmetric about its axle, so its orientation is the axle
/// direction alone: the relative pose's roll and yaw are those of the rotated axle.
class RailFrame {
 public:
  /// @param offset the rail's offset (not validated here: validate_contact_query does).
  /// @param pivot_y lateral position of the pivot the roll turns about [m].
  RailFrame(const RailOffset& offset, double pivot_y);

  /// The wheelset's pose relative to the rail (x unchanged).
  WheelsetPose relative_pose(const WheelsetPose& pose) const;
  /// d(relative y, z, roll, yaw) / d(y, z, roll, yaw) at pose [-, -, -, -] (y, z: a rotation;
  /// roll, yaw: through the axle).
  Eigen::Matrix4d pose_jacobian(const WheelsetPose& pose) const;
  /// d(relative y, z, roll, yaw) / dt at a fixed pose as the rail moves under the wheelset
  /// [m/s, m/s, rad/s, rad/s].
  Eigen::Vector4d pose_rate(const WheelsetPose& pose) const;
  /// The wheelset's motion in rail coordinates (centre moved, vectors rotated).
  WheelsetMotion to_rail(const WheelsetMotion& motion) const;

  /// A contact point found in rail coordinates, in the track frame: positions and the normal
  /// moved, the contact angle turned by the roll (left wheel +roll, right wheel -roll); the
  /// distance stays the vertical distance of the rail frame, the curvatures are the same.
  ContactPoint to_track(ContactPoint point) const;
  /// A wheel constraint found at relative_pose(pose), for the pose: gap_gradient = J^T
  /// gradient (J = pose_jacobian), gap_rate += gradient . pose_rate, contact_angle turned;
  /// gap and normal_z stay the rail frame's, so that N normal_z gap_gradient is still the normal
  /// force's generalised force.
  WheelConstraint to_track(WheelConstraint constraint, const WheelsetPose& pose, WheelSide side) const;

 private:
  Eigen::Vector3d to_rail_point(const Eigen::Vector3d& x) const;
  /// A contact angle of the rail frame in the track frame [rad].
  double track_angle(double angle, WheelSide side) const;
  RailOffset offset_;
  Eigen::Matrix3d rotation_;  // R
  Eigen::Vector3d pivot_;     // p
  Eigen::Vector3d shift_;     // d
};

}  // namespace wrc
