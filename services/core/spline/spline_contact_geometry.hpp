#pragma once
/// @file
/// The fitted spline contact geometry of a wheelset (Arnold's unified approach, section 4): per
/// wheel, every quantity of spline_fields.hpp as a tensor-product spline over (y, roll, yaw),
/// evaluated with one basis evaluation per wheel and configuration.

#include <array>
#include <vector>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/models/patch_builder.hpp"
#include "core/spline/spline_fields.hpp"
#include "core/spline/tensor_spline.hpp"

namespace wrc {

/// The configuration box of one wheel [m, rad, rad]: y in [y_min, y_max], |roll| <= roll_max,
/// |yaw| <= yaw_max. The right wheel's box is the left one's mirror image.
struct SplineBox {
  double y_min = 0, y_max = 0, roll_max = 0, yaw_max = 0;
  /// The box of the other wheel: y in [-y_max, -y_min], the same roll and yaw ranges.
  SplineBox mirrored() const { return {-y_max, -y_min, roll_max, yaw_max}; }
};

/// One wheel's spline evaluation at one configuration.
struct SplineEvaluation {
  /// The fields evaluated (spline_fields.hpp) [SI]: value[j] for j < the value_count asked of
  /// SplineContactGeometry::evaluate, NaN for the others.
  std::array<double, kSplineFieldCount> value{};
  /// d z_touch / d(y, roll, yaw) [m/m, m/rad, m/rad] (kGradient or kHessian).
  std::array<double, 3> z_gradient{};
  /// Second derivatives of z_touch, upper triangle (y,y), (y,roll), (y,yaw), (roll,roll),
  /// (roll,yaw), (yaw,yaw) [SI] (kHessian).
  std::array<double, 6> z_hessian{};
  /// d flange_clearance / d(y, roll, yaw) [SI] (kGradient or kHessian with derivative_fields 2).
  std::array<double, 3> clearance_gradient{};
};

/// Both wheels' fitted splines and what they were fitted for.
class SplineContactGeometry {
 public:
  /// @param wheels the left [0] and right [1] wheel's splines over (y, roll, yaw) with
  ///        kSplineFieldCount functions each, in SplineField order.
  /// @param left_box the left wheel's box (the right wheel's is mirrored).
  /// @param s_split flange split of the wheel profile [m] (wheel_sample.hpp).
  /// @param lateral_curvature_floor the conformal floor the Hertz fields were computed with [-].
  /// @throws std::invalid_argument for a wrong count of wheels or functions, a basis that is not
  ///         3-D, or a box the bases do not cover.
  SplineContactGeometry(std::vector<TensorSplineSet> wheels, SplineBox left_box, double s_split,
                        double lateral_curvature_floor);

  /// The box of one wheel.
  SplineBox box(WheelSide side) const;
  const SplineBox& left_box() const { return left_box_; }
  /// True when (y, roll, yaw) of pose lies in the wheel's box (1e-12 slack).
  bool inside(WheelSide side, const WheelsetPose& pose) const;
  /// "y = ... m is outside the spline model's box [..] m of the left wheel" or empty when inside.
  std::string outside_reason(WheelSide side, const WheelsetPose& pose) const;

  /// Evaluates one wheel at pose (no box check: outside, the end polynomials extrapolate): the
  /// values of the first value_count fields (kSplineQueryFieldCount: what a contact query uses;
  /// the cost falls with the count, and the fields left out are NaN), and with kGradient or
  /// kHessian the gradient and Hessian of z (both always: one-variable-at-a-time contraction,
  /// TensorSplineSet::query) and, for derivative_fields = 2, the flange clearance's gradient
  /// (derivative_fields = 1: NaN; a contact query needs only the clearance's value, the event
  /// function).
  /// @throws std::invalid_argument for derivative_fields other than 1 or 2.
  void evaluate(WheelSide side, const WheelsetPose& pose, SplineDerivatives derivatives, SplineEvaluation& out,
                int value_count = kSplineFieldCount, int derivative_fields = 2) const;

  /// The contact point of an evaluation at pose: positions shifted by the pose, the distance
  /// z - z_touch, the normal renormalised, marked a local minimum. Fields not evaluated are NaN
  /// (after a query's kSplineQueryFieldCount: theta, the rolling curvatures and distance_curvature).
  ContactPoint contact_point(WheelSide side, const WheelsetPose& pose, const SplineEvaluation& e) const;
  /// The Hertz shape from the fitted shape fields (floored when the fitted curvatures give
  /// B <= floor * A).
  PatchShape patch_shape(const SplineEvaluation& e) const;

  /// SHA-256 of the model data: per wheel and variable the degree and breakpoints, then every
  /// coefficient (function-major), as little-endian doubles (heartbeat_t.model_hash).
  std::string data_hash() const;

  const TensorSplineSet& wheel(WheelSide side) const { return wheels_[static_cast<size_t>(side)]; }
  double s_split() const { return s_split_; }
  double lateral_curvature_floor() const { return lateral_curvature_floor_; }

 private:
  std::vector<TensorSplineSet> wheels_;
  SplineBox left_box_;
  double s_split_;
  double lateral_curvature_floor_;
};

}  // namespace wrc
