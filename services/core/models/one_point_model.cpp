#include "core/models/one_point_model.hpp"

#include <sstream>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/patch_builder.hpp"
#include "core/models/query_validation.hpp"
#include "core/models/wheelset_motion.hpp"

namespace wrc {

std::string describe_pose(const WheelsetPose& pose) {
  std::ostringstream msg;
  msg << "y = " << pose.y << " m, z = " << pose.z << " m, roll = " << pose.roll << " rad, yaw = " << pose.yaw
      << " rad";
  return msg.str();
}

ContactPoint require_common_point(const WheelsetGeometry& geometry, WheelSide side, const WheelsetPose& pose,
                                  const PotentialPointSearch& search, double steepest_flange) {
  std::optional<ContactPoint> point = geometry.common_point(side, pose, search);
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
  return *point;
}

OnePointModel::OnePointModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : geometry_(std::move(geometry)), options_(options) {
  if (!geometry_) throw std::invalid_argument("OnePointModel: no geometry");
  options_.validate();
  steepest_flange_ = steepest_flange_point(geometry_->wheel_profile());
}

ContactResult OnePointModel::evaluate(const ContactQuery& query) const {
  validate_contact_query(query);
  const WheelsetMotion motion = WheelsetMotion::from_query(query);
  const PatchContext context{query, motion, fastsim_.get(query.fastsim_elements, query.fastsim_strips),
                             contact_modulus(query.material.shear_modulus, query.material.poisson_ratio)};
  ContactResult result;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const ContactPoint point = require_common_point(*geometry_, side, query.pose, options_.search, steepest_flange_);
    std::optional<ContactPatch> patch = one_point_patch(point, context, options_.lateral_curvature_floor);
    if (patch) result.patches.push_back(std::move(*patch));
  }
  for (const ContactPatch& patch : result.patches) add_to_resultant(patch, motion.centre, result);
  return result;
}

}  // namespace wrc
