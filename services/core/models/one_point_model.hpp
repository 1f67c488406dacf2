// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Hertzian one-point contact (Arnold, section 2/3): one Hertz ellipse per wheel at its common
/// point, the potential common point with the smallest distance, from the exact geometry.

#include <memory>
#include <vector>

#include "core/models/hertzian_model.hpp"

namespace wrc {

/// Model "onepoint". Per wheel, the common point at the query pose (a full potential-point scan
/// of the exact geometry, so the point jumps where the global minimum of the distance jumps).
///  - kRigid: the wheel's normal_load is the normal force N along the contact normal; Hertz from
///    force; penetration reported as 0. A wheel with load 0 gets no patch. The caller follows a
///    branch (tracked_s_wheel, event function of track_branch()); a wheel with a
///    second_tracked_s_wheel is in rigid two-point contact (track_two_point()): two patches with
///    their own loads and the second constraint in ContactResult::second_wheels.
///  - kElastic: penetration delta = -distance cos(contact_angle) (normal_penetration()), the
///    vertical overlap at the query's z projected on the normal; N = C_H delta^{3/2} when
///    delta > 0, otherwise the wheel gets no patch (lifted).
/// A wheel without any local minimum of the distance over its rail (shifted off the rail), or whose
/// flange has climbed onto the rail (flange_climb.hpp), throws
/// ContactConfigurationError.
class OnePointModel final : public HertzianContactModel {
 public:
  /// @throws std::invalid_argument for a null geometry or invalid options.
  explicit OnePointModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options = {});

  std::string name() const override { return "onepoint"; }

 private:
  WheelConstraint add_wheel_patches(WheelSide side, const PatchContext& context,
                                    ContactResult& result) const override;
  /// Rigid two-point contact of one wheel (ContactQuery::second_tracked_s_wheel): a patch at each
  /// of the two followed minima with its own load, the second point's constraint in
  /// result.second_wheels, the pair's event function (track_two_point()) in the returned one.
  WheelConstraint add_two_point_patches(WheelSide side, const std::vector<ContactPoint>& points,
                                        const PatchContext& context, ContactResult& result) const;
};

/// The common point of one wheel at pose, or ContactConfigurationError naming the wheel and the
/// pose when the wheel has no local minimum of the distance over its rail or its flange has climbed
/// onto the rail (check_flange_not_climbed() with the steepest flange point steepest_flange [m]).
ContactPoint require_common_point(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                  const PotentialPointSearch& search, double steepest_flange);

/// The checks of require_common_point() on a common point found otherwise (null: none found).
/// @throws ContactConfigurationError as require_common_point() does.
void check_common_point(const WheelsetGeometry& geometry, WheelSide side, const ContactPoint* point,
                        const WheelsetPose& pose, double steepest_flange);

/// "y = ... m, roll = ... rad, yaw = ... rad" for error messages.
std::string describe_pose(const WheelsetPose& pose);

}  // namespace wrc
