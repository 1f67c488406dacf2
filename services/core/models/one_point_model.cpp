#include "core/models/one_point_model.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/patch_builder.hpp"
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
  const TrackedBranch branch = track_branch(points, context.query.tracked_s_wheel[static_cast<size_t>(side)]);
  const ContactPoint& point = points[branch.index];
  check_common_point(*geometry_, side, &point, pose, steepest_flange_);
  std::optional<ContactPatch> patch = one_point_patch(point, context, options_.lateral_curvature_floor);
  if (patch) result.patches.push_back(std::move(*patch));
  return exact_point_constraint(point, pose, branch.switch_function, branch.switch_s_wheel);
}

}  // namespace wrc
