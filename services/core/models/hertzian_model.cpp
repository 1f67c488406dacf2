// SPDX-License-Identifier: Apache-2.0
#include "core/models/hertzian_model.hpp"

#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/model_interface/rail_frame.hpp"
#include "core/model_interface/wheelset_motion.hpp"
#include "core/models/contact_range.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/one_point_model.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {

HertzianContactModel::HertzianContactModel(std::shared_ptr<const WheelsetGeometry> geometry,
                                           ContactModelOptions options, const std::string& model)
    : geometry_(std::move(geometry)), options_(options) {
  if (!geometry_) throw std::invalid_argument(model + ": no geometry");
  options_.validate();
  steepest_flange_ = steepest_flange_point(geometry_->wheel_profile());
}

ContactResult HertzianContactModel::evaluate(const ContactQuery& query) const {
  validate_contact_query(query);
  const WheelsetMotion motion = WheelsetMotion::from_query(query);
  const PatchContext context{query, motion, fastsim_.get(query.fastsim_elements, query.fastsim_strips),
                             contact_modulus(query.material.shear_modulus, query.material.poisson_ratio)};
  ContactResult result;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const size_t wheel = static_cast<size_t>(side);
    if (query.rail_offsets[wheel].nominal()) {
      result.wheels[wheel] = add_wheel_patches(side, context, result);
    } else {
      add_moved_rail_patches(side, context, result);
    }
  }
  check_contact_range(query, result);
  for (const ContactPatch& patch : result.patches) add_to_resultant(patch, motion.centre, result);
  return result;
}

void HertzianContactModel::add_moved_rail_patches(WheelSide side, const PatchContext& context,
                                                  ContactResult& result) const {
  // The wheel against its nominal rail in the moved rail's coordinates, the answer carried back
  // into the track frame (rail_frame.hpp).
  const size_t wheel = static_cast<size_t>(side);
  const double pivot_y = (side == WheelSide::kLeft ? 1.0 : -1.0) * geometry_->track().taping_half_distance();
  const RailFrame frame(context.query.rail_offsets[wheel], pivot_y);
  ContactQuery query = context.query;
  query.pose = frame.relative_pose(context.query.pose);
  const WheelsetMotion motion = frame.to_rail(context.motion);
  const PatchContext rail_context{query, motion, context.fastsim, context.contact_modulus};
  ContactResult in_rail;
  const WheelConstraint constraint = add_wheel_patches(side, rail_context, in_rail);
  result.wheels[wheel] = frame.to_track(constraint, context.query.pose, side);
  if (in_rail.second_wheels[wheel])
    result.second_wheels[wheel] = frame.to_track(*in_rail.second_wheels[wheel], context.query.pose, side);
  for (ContactPatch& patch : in_rail.patches) {
    patch.point = frame.to_track(patch.point);
    result.patches.push_back(std::move(patch));
  }
}

ContactPoint HertzianContactModel::exact_common_point(WheelSide side, const WheelsetPose& pose) const {
  return require_common_point(*geometry_, side, pose, options_.search, steepest_flange_);
}

}  // namespace wrc
