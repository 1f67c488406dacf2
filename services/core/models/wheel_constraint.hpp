// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The constraint of one wheel (WheelConstraint) from a contact point of the exact geometry or of
/// a model: the vertical gap, its gradient with respect to the pose, the branch's event function.

#include <vector>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// The axes of the pose's rotations: roll about e_x' = Rz(yaw) e_x, yaw about e_z, spin about
/// e_axle = Rz(yaw) Rx(roll) e_y (track frame) [-].
struct PoseAxes {
  Eigen::Vector3d roll;
  Eigen::Vector3d yaw;
  Eigen::Vector3d axle;
  static PoseAxes at(const WheelsetPose& pose);
};

/// d distance / d(y, z, roll, yaw) of a contact point at pose [-, -, m/rad, m/rad]. The vertical
/// distance of a potential point is stationary along the curve C, so to first order it changes
/// only through the rigid motion of the wheel material at the point (envelope theorem): a
/// displacement dr of the wheel point changes the vertical distance to the prismatic rail by
/// n . dr / n_z, with dr = e_y dy, e_z dz, (e_x' x rho) droll, (e_z x rho) dyaw and rho the wheel
/// point relative to the wheelset centre.
Eigen::Vector4d vertical_gap_gradient(const ContactPoint& point, const WheelsetPose& pose);

/// The WheelConstraint of a point of the exact geometry (or of an interpolation of it): gap =
/// distance, gradient by vertical_gap_gradient(), with the given event function and switch target.
WheelConstraint exact_point_constraint(const ContactPoint& point, const WheelsetPose& pose, double switch_function,
                                       double switch_s_wheel);

/// How far the nearest minimum may lie from the followed point's last position before the
/// followed branch counts as vanished [m].
constexpr double kBranchLostDistance = 3e-3;

/// The branch of one wheel's potential points that a rigid one-point contact follows.
struct TrackedBranch {
  size_t index = 0;                 ///< index of the followed local minimum in the point list
  double switch_function = kNoSwitch;  ///< see WheelConstraint::switch_function [m]
  double switch_s_wheel = 0;        ///< s of the minimum to follow after the switch [m] (NaN: none)
};

/// Chooses the followed minimum among points (potential points of one wheel, ordered by s, at
/// least one a minimum): the minimum nearest to tracked_s [m], or the lowest one when tracked_s is
/// NaN. Its event function is the smallest of (distance of another minimum - distance of the
/// followed one) and (distance of a neighbouring maximum - distance of the followed one): > 0
/// while the followed point is the lowest, continuous, 0 where another minimum becomes as low
/// (the one-point contact point jumps) or the followed minimum merges with a maximum and vanishes.
/// The switch target is the other minimum that is lowest.
/// A followed minimum that has vanished (the nearest minimum lies more than kBranchLostDistance
/// from tracked_s: beyond the fold the event function has no continuation) gives a negative event
/// function, so that an integrator brackets the fold as the sign change, and the lowest minimum
/// as the target. The caller updates tracked_s with every accepted step, along which a contact
/// point moves much less than that.
/// @throws std::invalid_argument when points holds no minimum.
TrackedBranch track_branch(const std::vector<ContactPoint>& points, double tracked_s);

/// The two minima a wheel in rigid two-point contact follows (ContactQuery::second_tracked_s_wheel).
struct TwoPointBranches {
  size_t first = 0;                    ///< index of the minimum nearest tracked_s
  size_t second = 0;                   ///< index of the other minimum nearest second_s (== first: none)
  double switch_function = kNoSwitch;  ///< > 0 while both are minima and no third one is lower [m]
  double switch_s_wheel = 0;           ///< s to follow alone after its root [m]
};

/// Chooses the two followed minima among points (as track_branch(), the second one other than the
/// first). The event function is the smallest of (distance of a third minimum - the lower of the
/// pair's distances), with that minimum as the target, and (distance of a maximum next to one of
/// the pair - that one's distance), with the other one of the pair as the target: the pair is
/// left where a third point becomes lower or one of the pair merges with a maximum and vanishes.
/// A pair member that has vanished already (no minimum within kBranchLostDistance of its tracked
/// s, or no second minimum at all) gives -kBranchLostDistance with the surviving one (or the
/// lowest minimum) as the target. Where both lie within a normal force's reach of each other the
/// caller's constraints hold both distances at 0; releasing one is the caller's event (its normal
/// force falling through 0).
/// @throws std::invalid_argument when points holds no minimum.
TwoPointBranches track_two_point(const std::vector<ContactPoint>& points, double tracked_s, double second_s);

}  // namespace wrc
