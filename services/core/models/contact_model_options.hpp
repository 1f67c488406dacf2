#pragma once
/// @file
/// Settings shared by the contact models built by make_contact_model(): the potential-point scan,
/// the fallback for non-Hertzian (conformal) curvatures and the interpolation table of the
/// interpolated Hertzian model.

#include "core/geometry/potential_points.hpp"

namespace wrc {

/// How the interpolated model interpolates its table in the lateral shift y.
enum class YInterpolation {
  kLinear,       ///< piecewise linear in y (continuous, no overshoot at contact-point jumps)
  kCubicSpline,  ///< natural cubic spline in y through the nodes (C2, overshoots next to jumps)
};

/// The interpolation configurations of the interpolated Hertzian model (MEDYNA style): a tensor
/// grid of equally spaced nodes y_i in [-y_max, y_max], roll_j in [-roll_max, roll_max] and
/// yaw_k in [-yaw_max, yaw_max]. Roll and yaw are always interpolated linearly.
struct InterpolationGrid {
  int y_points = 41;       ///< nodes in y [-], >= 2 (41 over +-10 mm: 0.5 mm spacing)
  double y_max = 0.010;    ///< half range in y [m], > 0
  int roll_points = 3;     ///< nodes in roll [-], >= 2
  double roll_max = 0.015; ///< half range in roll [rad], > 0 (rigid contact reaches ~11 mrad at y = 10 mm)
  int yaw_points = 3;      ///< nodes in yaw [-], >= 2
  double yaw_max = 0.010;  ///< half range in yaw [rad], > 0
  YInterpolation y_method = YInterpolation::kLinear;  ///< interpolation in y

  /// Throws std::invalid_argument naming the first count < 2 (or > 10000) or range that is not
  /// positive and finite.
  void validate() const;
};

/// Options of every contact model.
struct ContactModelOptions {
  /// Potential-point scan of the exact geometry (step and root tolerance in s [m]).
  PotentialPointSearch search;
  /// Fallback for conformal contact (flange root: concave wheel on a flatter rail, B <= 0):
  /// the lateral relative curvature B is raised to at least lateral_curvature_floor * A, A the
  /// rolling relative curvature [-]. The default 0.01 caps the lateral relative radius at 100
  /// times the rolling one, which gives a/b ~ 1/16, inside Kalker's tabulated range. Hertz's
  /// theory does not hold there (the real patch is non-elliptic and conformal); the floor only
  /// keeps the model usable, and ContactPatch::lateral_curvature_floored flags such patches.
  /// 0 disables the floor: a patch with B <= 0 then throws ContactConfigurationError.
  double lateral_curvature_floor = 0.01;
  /// Table of the interpolated model (ignored by the others).
  InterpolationGrid interp;

  /// Throws std::invalid_argument naming the first invalid value (floor negative or NaN, search
  /// step or tolerance not positive, or an invalid grid).
  void validate() const;
};

}  // namespace wrc
