// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Settings shared by the contact models built by make_contact_model(): the potential-point scan,
/// the fallback for non-Hertzian (conformal) curvatures and the interpolation table of the
/// interpolated Hertzian model.

#include "core/geometry/potential_points.hpp"
#include "core/model_interface/jump_transition.hpp"

namespace wrc {

/// The interpolation configurations of the interpolated Hertzian model (MEDYNA style, on the rigid
/// manifold): equally spaced nodes y_i in [-y_max, y_max] (around each jump of the common point,
/// its band's two ends instead: ContactPointTable) and yaw_k in [-yaw_max, yaw_max]; at each
/// (y_i, yaw_k) the rigid wheelset's roll phi_r and height, and roll_points roll nodes
/// phi_r + delta_j with delta_j equally spaced in [-roll_band, roll_band] (an odd count, so that
/// delta = 0, the rigid roll itself, is a node). Interpolated by cubic Hermite pieces in y and in
/// delta and by the Lagrange polynomial through the yaw nodes (ContactPointTable).
struct InterpolationGrid {
  int y_points = 121;        ///< nodes in y [-], >= 2 (121 over +-10 mm: 1/6 mm spacing)
  double y_max = 0.010;      ///< half range in y [m], > 0
  int roll_points = 3;       ///< roll nodes about the rigid roll [-], odd, 3..9
  double roll_band = 0.002;  ///< half range of the roll nodes about the rigid roll [rad], > 0
  /// Largest |roll| a query may have [rad], > 0 (beyond the band the table extrapolates: the
  /// distance linearly in delta, the other parameters held at the band's edge).
  double roll_max = 0.015;
  int yaw_points = 3;        ///< nodes in yaw [-], 2..9 (the Lagrange polynomial's degree + 1)
  double yaw_max = 0.010;    ///< half range in yaw [rad], > 0, <= kMaxValidatedYaw
  /// Cap on the half-width, in the difference of the two points' touching heights, of the band
  /// around a jump of the common point over which the table ramps from one point to the other
  /// [m], in [0, kMaxTransition]; the half-width is the smaller of this and the Hertz approach at
  /// transition_load, as the spline model's (core/model_interface/jump_transition.hpp). A jump
  /// whose other branch folds away within that range (S1002/UIC60's centred jump), and every jump
  /// when this is 0, is smoothed over one y cell (MEDYNA's table).
  double transition = kDefaultTransition;
  /// Normal load per wheel whose Hertz approach sets the bands [N], in [1, 1e6].
  double transition_load = kDefaultTransitionLoad;

  /// Throws std::invalid_argument naming the first count out of its range (y_points 2..10000,
  /// roll_points odd 3..9, yaw_points 2..9), range that is not positive and finite, or transition
  /// value outside its range.
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
