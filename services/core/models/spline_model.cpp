#include "core/models/spline_model.hpp"

#include <sstream>
#include <stdexcept>

namespace wrc {

SplineModel::SplineModel(std::shared_ptr<const WheelsetGeometry> geometry,
                         std::shared_ptr<const SplineContactGeometry> splines, ContactModelOptions options)
    : HertzianContactModel(std::move(geometry), options, "SplineModel"), splines_(std::move(splines)) {
  if (!splines_) throw std::invalid_argument("SplineModel: no fitted splines (fit_spline_geometry or wrc-geometryd)");
  if (options_.lateral_curvature_floor != splines_->lateral_curvature_floor()) {
    std::ostringstream msg;
    msg << "SplineModel: lateral_curvature_floor = " << options_.lateral_curvature_floor
        << " but the splines' Hertz shapes were fitted with " << splines_->lateral_curvature_floor();
    throw std::invalid_argument(msg.str());
  }
}

void SplineModel::add_wheel_patches(WheelSide side, const PatchContext& context, ContactResult& result) const {
  const WheelsetPose& pose = context.query.pose;
  if (!splines_->inside(side, pose)) throw OutsideModelError(splines_->outside_reason(side, pose));
  SplineEvaluation e;
  splines_->evaluate(side, pose, SplineDerivatives::kValue, e);
  std::optional<ContactPatch> patch;
  if (e.value[kFieldFlangeClearance] > 0.0) {
    patch = one_point_patch(splines_->contact_point(side, pose, e), splines_->patch_shape(e), context);
  } else {
    patch = one_point_patch(exact_common_point(side, pose), context, options_.lateral_curvature_floor);
  }
  if (patch) result.patches.push_back(std::move(*patch));
}

}  // namespace wrc
