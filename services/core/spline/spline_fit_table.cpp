// SPDX-License-Identifier: Apache-2.0
#include "core/spline/spline_fit_table.hpp"

#include "core/geometry/wheelset_geometry.hpp"
#include "core/model_interface/jump_transition.hpp"

namespace wrc {

const std::vector<Parameter<SplineFitOptions>>& spline_fit_table() {
  using O = SplineFitOptions;
  constexpr auto kNumber = ParameterKind::kNumber;
  static const std::vector<Parameter<O>> table{
      member_parameter<O>({"y_min", "", "m", "left wheel's box: lowest lateral shift (--box)", kNumber,
                           closed(-kMaxGeometryLateralShift, kMaxGeometryLateralShift)}, &O::y_min),
      member_parameter<O>({"y_max", "", "m", "left wheel's box: highest lateral shift (--box)", kNumber,
                           closed(-kMaxGeometryLateralShift, kMaxGeometryLateralShift)}, &O::y_max),
      member_parameter<O>({"roll_max", "", "rad", "roll in [-roll_max, roll_max] (--box; beyond 0.05 a wheel lifts)",
                           kNumber, {0.0, Bound::kOpen, 0.05, Bound::kClosed}}, &O::roll_max),
      member_parameter<O>({"yaw_max", "", "rad", "yaw in [-yaw_max, yaw_max] (--box; the validated geometry)",
                           kNumber, {0.0, Bound::kOpen, kMaxValidatedYaw, Bound::kClosed}}, &O::yaw_max),
      member_parameter<O>({"grading", "", "-", "graded knots: extra density where jumps sweep", kNumber, kNonNegative},
                          &O::grading),
      member_parameter<O>({"sample_step_y", "--sample-step", "m", "spacing of the samples in y", kNumber, kPositive},
                          &O::sample_step_y),
      member_parameter<O>({"roll_samples", "", "-", "exact-geometry samples in roll (--samples)",
                           ParameterKind::kInteger, closed(1, 101)}, &O::roll_samples),
      member_parameter<O>({"yaw_samples", "", "-", "exact-geometry samples in yaw (--samples)",
                           ParameterKind::kInteger, closed(1, 101)}, &O::yaw_samples),
      member_parameter<O>({"jump_weight", nullptr, "-", "weight of samples near a tread jump of the common point",
                           kNumber, {0.0, Bound::kOpen, 1.0, Bound::kClosed}}, &O::jump_weight),
      member_parameter<O>({"jump_band", nullptr, "m", "half-width in y of the down-weighted band around each jump",
                           kNumber, kNonNegative}, &O::jump_band),
      member_parameter<O>({"transition", nullptr, "m",
                           "largest half-width of the blend between branch fits at a jump, in the difference of "
                           "their touching heights (0: one fit across the jumps)",
                           kNumber, closed(0.0, kMaxTransition)}, &O::transition),
      member_parameter<O>({"transition_load", nullptr, "N",
                           "normal load per wheel whose Hertz approach sets the blend's half-width",
                           kNumber, closed(kMinTransitionLoad, kMaxTransitionLoad)}, &O::transition_load),
      member_parameter<O>({"flange_angle", "--flange-region-angle", "rad", "profile slope angle that starts the flange region",
                           kNumber, {0.1, Bound::kOpen, 1.5, Bound::kOpen}}, &O::flange_angle),
      member_parameter<O>({"clearance_cap", "", "m", "cap of the fitted flange clearance", kNumber, kPositive},
                          &O::clearance_cap),
  };
  return table;
}

}  // namespace wrc
