// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The fitted spline contact geometry of a wheelset (Arnold's unified approach, section 4): per
/// wheel, every quantity of spline_fields.hpp as a tensor-product spline over (y, roll, yaw),
/// evaluated with one basis evaluation per wheel and configuration.

#include <array>
#include <limits>
#include <vector>

#include "core/geometry/contact_point.hpp"
#include "core/geometry/wheelset_pose.hpp"
#include "core/model_interface/patch_builder.hpp"
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
  /// Within a transition (0 < upper_share < 1): the share of the load the upper branch's point
  /// carries [-] and both branches' own fields [SI] (their fitted normals and angles); NaN share
  /// elsewhere.
  double upper_share = std::numeric_limits<double>::quiet_NaN();
  std::array<double, kSplineFieldCount> lower_value{}, upper_value{};
  /// Within a transition, with a gradient evaluated: each branch's dz/dy [-], and the fields'
  /// normal and contact angle replaced by those of this slope (as for the blend's own).
  double lower_slope = std::numeric_limits<double>::quiet_NaN(), upper_slope = lower_slope;
};

/// Where the tread contact point of one wheel jumps, as a function of roll and yaw: y_jump =
/// sum over a, b in 0..2 of c[3 a + b] roll^a yaw^b [m] (least squares over the jumps found on
/// the sample lines).
struct JumpSurface {
  std::array<double, 9> c{};  ///< coefficients [m / rad^(a + b)]
  /// Half-width of the blend of the two branches in the difference of their touching heights,
  /// d = z_above - z_below [m], > 0: within |d| < height_half_width the elastic contact shares
  /// the load between both points (docs/spline-model.md, "Branches and the transition").
  double height_half_width = 0;
  /// Largest |y - y_jump| at which |d| < height_half_width on the sample lines [m], > 0: beyond
  /// it the pose's branch alone is evaluated.
  double y_reach = 0;
  /// y_jump at (roll, yaw) [m].
  double at(double roll, double yaw) const {
    return (c[0] + yaw * (c[1] + yaw * c[2])) + roll * ((c[3] + yaw * (c[4] + yaw * c[5])) + roll * (c[6] + yaw * (c[7] + yaw * c[8])));
  }
  /// y_jump and its derivatives d/droll, d/dyaw [m, m/rad, m/rad] and d2/droll2, d2/droll dyaw,
  /// d2/dyaw2 [m/rad^2] at (roll, yaw) [rad].
  void evaluate(double roll, double yaw, double& value, double* gradient, double* hessian) const;
};

/// One wheel's fitted splines: branches[0..J] in increasing y, branch m the tread contact point
/// between jumps[m - 1] and jumps[m], each fitted on its own basis over the stretch of y where it
/// is used (its own with the transitions), and blended C2 into its neighbour as a smooth maximum
/// of their touching heights (JumpSurface::height_half_width). Without jumps one spline (the
/// paper's form: one fit across every jump).
struct SplineWheel {
  std::vector<TensorSplineSet> branches;  ///< kSplineFieldCount functions each, SplineField order
  std::vector<JumpSurface> jumps;         ///< branches.size() - 1 jump surfaces, increasing in y
};

/// Both wheels' fitted splines and what they were fitted for.
class SplineContactGeometry {
 public:
  /// @param wheels the left [0] and right [1] wheel's branches over (y, roll, yaw).
  /// @param left_box the left wheel's box (the right wheel's is mirrored).
  /// @param s_split flange split of the wheel profile [m] (wheel_sample.hpp).
  /// @param lateral_curvature_floor the conformal floor the Hertz fields were computed with [-].
  /// @throws std::invalid_argument for a wrong count of wheels, branches or functions, a basis
  ///         that is not 3-D, a box the bases do not cover (all branches together), or a jump
  ///         whose height_half_width or y_reach is not positive and finite.
  SplineContactGeometry(std::array<SplineWheel, 2> wheels, SplineBox left_box, double s_split,
                        double lateral_curvature_floor);

  /// The box of one wheel.
  SplineBox box(WheelSide side) const;
  const SplineBox& left_box() const { return left_box_; }
  /// True when (y, roll, yaw) of pose lies in the wheel's box (1e-12 slack).
  bool inside(WheelSide side, const WheelsetPose& pose) const;
  /// "y = ... m is outside the spline model's box [..] m of the left wheel" or empty when inside.
  std::string outside_reason(WheelSide side, const WheelsetPose& pose) const;

  /// Evaluates one wheel at pose (no box check: outside, the end polynomials extrapolate): the
  /// branch of the pose, or near a jump (|y - y_jump| < y_reach and |d| < height_half_width, d
  /// the upper branch's z minus the lower's) the smooth maximum of the two branches' z,
  /// z_a + h phi(d / h), every other field blended with phi' = w (the upper point's share),
  /// w(u) = u^3 (10 - 15 u + 6 u^2), u = (1 + d / h) / 2: the gradient of z a convex combination
  /// of the branches' (values, gradient and Hessian of the blend);
  /// the values of the first value_count fields (kSplineQueryFieldCount: what a contact query uses;
  /// the cost falls with the count, and the fields left out are NaN), and with kGradient or
  /// kHessian the gradient and Hessian of z (both always: one-variable-at-a-time contraction,
  /// TensorSplineSet::query) and, for derivative_fields = 2, the flange clearance's gradient
  /// (derivative_fields = 1: NaN; a contact query needs only the clearance's value, the event
  /// function). With kGradient or kHessian the creep frame follows the gradient g = dz/dy of the
  /// evaluated z (the constraint's lateral direction): normal (0, -g, 1) / sqrt(1 + g^2), contact
  /// angle atan(sign g) (sign +1 left, -1 right), replacing the fitted normal and angle.
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

  /// SHA-256 of the model data: per wheel its jump surfaces' coefficients, height half-widths and
  /// y reaches,
  /// and per branch and variable the degree and breakpoints, then every coefficient
  /// (function-major), as little-endian doubles on every host (sha256_hex_of_doubles;
  /// heartbeat_t.model_hash).
  std::string data_hash() const;

  const SplineWheel& wheel(WheelSide side) const { return wheels_[static_cast<size_t>(side)]; }
  double s_split() const { return s_split_; }
  double lateral_curvature_floor() const { return lateral_curvature_floor_; }

 private:
  std::array<SplineWheel, 2> wheels_;
  SplineBox left_box_;
  double s_split_;
  double lateral_curvature_floor_;
};

}  // namespace wrc
