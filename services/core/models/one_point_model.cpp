// SPDX-License-Identifier: Apache-2.0
#include "core/models/one_point_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {

std::string describe_pose(const WheelsetPose& pose) {
  std::ostringstream msg;
  msg << "y = " << pose.y << " m, z = " << pose.z << " m, roll = " << pose.roll << " rad, yaw = " << pose.yaw
      << " rad";
  return msg.str();
}

void check_common_point(const WheelsetGeometry& geometry, WheelSide side, const ContactPoint* point,
                        const WheelsetPose& pose, double steepest_flange) {
  if (!point) {
    throw ContactConfigurationError(std::string("the ") + side_name(side) +
                                    " wheel has no contact point on its rail (shifted off the rail or flange "
                                    "climbed over) at " +
                                    describe_pose(pose));
  }
  if (geometry.beyond_flange_apex(*point)) {
    throw ContactConfigurationError(std::string("the ") + side_name(side) +
                                    " wheel's flange has climbed onto its rail: contact at s = " +
                                    std::to_string(point->s) + " m on or beyond the flange apex, at " +
                                    describe_pose(pose));
  }
  check_flange_not_climbed(*point, steepest_flange, pose);
}

ContactPoint require_common_point(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                  const PotentialPointSearch& search, double steepest_flange) {
  std::optional<ContactPoint> point = geometry.common_point(side, pose, search);
  check_common_point(geometry, side, point ? &*point : nullptr, pose, steepest_flange);
  return *point;
}

OnePointModel::OnePointModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : HertzianContactModel(std::move(geometry), options, "OnePointModel") {}

WheelConstraint OnePointModel::add_wheel_patches(WheelSide side, const PatchContext& context,
                                                 ContactResult& result) const {
  const WheelsetPose& pose = context.query.pose;
  const std::vector<ContactPoint> points = geometry_->potential_points(side, pose, options_.search);
  const bool any_minimum = std::any_of(points.begin(), points.end(), [](const ContactPoint& p) { return p.is_minimum; });
  if (!any_minimum) check_common_point(*geometry_, side, nullptr, pose, steepest_flange_);
  const size_t wheel = static_cast<size_t>(side);
  if (context.query.formulation == ContactFormulation::kRigid && !std::isnan(context.query.second_tracked_s_wheel[wheel]))
    return add_two_point_patches(side, points, context, result);
  const TrackedBranch branch = track_branch(points, context.query.tracked_s_wheel[wheel]);
  const ContactPoint& point = points[branch.index];
  check_common_point(*geometry_, side, &point, pose, steepest_flange_);
  std::optional<ContactPatch> patch = one_point_patch(point, context, options_.lateral_curvature_floor);
  if (patch) result.patches.push_back(std::move(*patch));
  return exact_point_constraint(point, pose, branch.switch_function, branch.switch_s_wheel);
}

WheelConstraint OnePointModel::add_two_point_patches(WheelSide side, const std::vector<ContactPoint>& points,
                                                     const PatchContext& context, ContactResult& result) const {
  const size_t wheel = static_cast<size_t>(side);
  const WheelsetPose& pose = context.query.pose;
  const TwoPointBranches pair =
      track_two_point(points, context.query.tracked_s_wheel[wheel], context.query.second_tracked_s_wheel[wheel]);
  const ContactPoint& first = points[pair.first];
  const ContactPoint& second = points[pair.second];
  check_common_point(*geometry_, side, &first, pose, steepest_flange_);
  check_common_point(*geometry_, side, &second, pose, steepest_flange_);
  // Each point carries its own load (a vanished second point, pair.second == pair.first, carries
  // none: the event function is negative there and the caller leaves the pair).
  std::optional<ContactPatch> patch = one_point_patch(first, context, options_.lateral_curvature_floor);
  if (patch) result.patches.push_back(std::move(*patch));
  const double second_load = context.query.second_normal_load[wheel];
  if (pair.second != pair.first && second_load > 0.0)
    result.patches.push_back(
        patch_from_force(second, contact_shape(second, options_.lateral_curvature_floor), second_load, context));
  result.second_wheels[wheel] = exact_point_constraint(second, pose, kNoSwitch, std::numeric_limits<double>::quiet_NaN());
  return exact_point_constraint(first, pose, pair.switch_function, pair.switch_s_wheel);
}

}  // namespace wrc
