#include "core/models/hertzian_model.hpp"

#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/model_interface/query_validation.hpp"
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
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight})
    result.wheels[static_cast<size_t>(side)] = add_wheel_patches(side, context, result);
  check_contact_range(query, result);
  for (const ContactPatch& patch : result.patches) add_to_resultant(patch, motion.centre, result);
  return result;
}

ContactPoint HertzianContactModel::exact_common_point(WheelSide side, const WheelsetPose& pose) const {
  return require_common_point(*geometry_, side, pose, options_.search, steepest_flange_);
}

}  // namespace wrc
