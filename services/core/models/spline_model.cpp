// SPDX-License-Identifier: Apache-2.0
#include "core/models/spline_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/models/one_point_model.hpp"
#include "core/models/wheel_constraint.hpp"

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

bool SplineModel::any_flange_side_minimum(const std::vector<ContactPoint>& points) const {
  return std::any_of(points.begin(), points.end(),
                     [this](const ContactPoint& p) { return p.is_minimum && p.s <= splines_->s_split(); });
}

bool SplineModel::has_flange_side_minimum(WheelSide side, const WheelsetPose& pose) const {
  return any_flange_side_minimum(geometry_->potential_points(side, pose, options_.search));
}

WheelConstraint SplineModel::add_wheel_patches(WheelSide side, const PatchContext& context,
                                               ContactResult& result) const {
  const WheelsetPose& pose = context.query.pose;
  if (!splines_->inside(side, pose)) throw OutsideModelError(splines_->outside_reason(side, pose));
  SplineEvaluation e;
  // What a patch and the constraint use: the query fields, z's derivatives (the clearance is an
  // event function: its value suffices).
  splines_->evaluate(side, pose, SplineDerivatives::kGradient, e, kSplineQueryFieldCount, 1);
  const double clearance = e.value[kFieldFlangeClearance];
  const double tracked = context.query.tracked_s_wheel[static_cast<size_t>(side)];
  // Flange contact where the fitted clearance and the exact geometry both say so when untracked (a
  // first query); tracked, where the followed point lies on the flange side. The exact geometry is
  // asked once, only untracked or on the tread where the fit says flange contact.
  const bool untracked = std::isnan(tracked);
  const bool on_tread = !untracked && tracked > splines_->s_split();
  const bool fitted_flange = !(clearance > 0.0);
  const bool exact_flange = fitted_flange && (untracked || on_tread) && has_flange_side_minimum(side, pose);
  const bool flange_contact = untracked ? exact_flange : !on_tread;
  if (!flange_contact) {
    const ContactPoint point = splines_->contact_point(side, pose, e);
    std::optional<ContactPatch> patch = one_point_patch(point, splines_->patch_shape(e), context);
    if (patch && e.upper_share > 0.0 && e.upper_share < 1.0) {
      // Within a transition the wheel touches at both branches' points (add_shared_patches()).
      std::array<SharedPoint, 2> parts;
      for (int k = 0; k < 2; ++k) {
        SplineEvaluation part = e;
        part.value = k == 0 ? e.lower_value : e.upper_value;
        parts[k] = {splines_->contact_point(side, pose, part), splines_->patch_shape(part),
                    k == 0 ? 1.0 - e.upper_share : e.upper_share, k == 0 ? e.lower_slope : e.upper_slope};
      }
      add_shared_patches(*patch, e.z_gradient[0], parts, context, result);
      patch.reset();
    }
    if (patch) result.patches.push_back(std::move(*patch));
    WheelConstraint c;
    c.gap = point.distance;  // z - z_touch(y, roll, yaw)
    c.gap_gradient = Eigen::Vector4d(-e.z_gradient[0], 1.0, -e.z_gradient[1], -e.z_gradient[2]);
    c.normal_z = point.normal.z();
    c.s_wheel = point.s;
    c.contact_angle = point.contact_angle;
    c.switch_function = clearance;          // flange contact begins where it falls through 0
    c.switch_s_wheel = splines_->s_split();  // a tracked s <= s_split selects flange contact
    // The fitted clearance is within its fit's accuracy of the exact one, not its sign: where it
    // falls below 0 but the exact geometry has no minimum on the flange side, flange contact would
    // find none to follow and come back to the tread at once (a switch back and forth without
    // end). The tread stays: the switch function is mirrored above 0 until the exact flange
    // minimum exists.
    if (fitted_flange && !exact_flange) c.switch_function = -clearance;
    return c;
  }
  // Flange contact: the exact geometry's minimum on the flange side of the split.
  const std::vector<ContactPoint> points = geometry_->potential_points(side, pose, options_.search);
  std::vector<ContactPoint> flange_side;
  for (const ContactPoint& p : points)
    if (p.s <= splines_->s_split()) flange_side.push_back(p);
  const std::vector<ContactPoint>& candidates = any_flange_side_minimum(points) ? flange_side : points;
  if (!std::any_of(candidates.begin(), candidates.end(), [](const ContactPoint& p) { return p.is_minimum; }))
    check_common_point(*geometry_, side, nullptr, pose, steepest_flange_);
  const TrackedBranch branch = track_branch(candidates, tracked);
  const ContactPoint& point = candidates[branch.index];
  check_common_point(*geometry_, side, &point, pose, steepest_flange_);
  std::optional<ContactPatch> patch = one_point_patch(point, context, options_.lateral_curvature_floor);
  if (patch) result.patches.push_back(std::move(*patch));
  // Back to the fitted tread where the clearance rises through 0 again, to another flange point
  // where the exact minima cross.
  if (-clearance < branch.switch_function)
    return exact_point_constraint(point, pose, -clearance, e.value[kFieldSWheel]);
  return exact_point_constraint(point, pose, branch.switch_function, branch.switch_s_wheel);
}

}  // namespace wrc
