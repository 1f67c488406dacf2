// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The jumps of the common point on the rigid manifold (the rigid wheelset at lateral shift y and
/// yaw, both wheels touching) and, around each, the band of y in which an elastic contact loads
/// both points (core/model_interface/jump_transition.hpp): where the interpolation table ramps
/// from one point to the other.

#include <vector>

#include "core/geometry/potential_points.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/geometry/wheel_side.hpp"

namespace wrc {

/// What sets the bands.
struct JumpTransitionOptions {
  /// Cap on the half-width in height [m], in [0, kMaxTransition]; 0: no band (empty result).
  double transition = 0;
  /// Normal load per wheel whose Hertz approach is the half-width in height [N].
  double transition_load = 0;
  /// As ContactModelOptions::lateral_curvature_floor, for the Hertz shape of the two points [-].
  double lateral_curvature_floor = 0;
  /// Step of the walk that follows each branch past the jump [m]: the band's resolution, and its
  /// least half-width on a side where the branch vanishes within one step.
  double trace_step = 1e-5;
  PotentialPointSearch search;
};

/// One jump of one wheel's common point and its band.
struct JumpTransition {
  WheelSide side = WheelSide::kLeft;
  double yaw = 0;                ///< [rad]
  double y = 0;                  ///< where the two minima are equally low (within 10 nm) [m]
  double approach = 0;           ///< mean Hertz approach of the two points at the jump [m]
  double height_half_width = 0;  ///< h: the smallest of the approach, the cap and a branch's fold [m]
  double y_low = 0;              ///< below it the lower-y branch's point alone carries load [m]
  double y_high = 0;             ///< above it the higher-y branch's point alone [m]
  /// A branch vanishes (folds) before the two heights differ by the approach (or the cap): h is
  /// the fold's height, and the elastic contact shares its load over a wider range than the two
  /// branches span (S1002 on UIC60 at the centre: h = 8.8 um against an approach of 82 um).
  bool folded = false;
};

/// The jumps of either wheel's common point between neighbouring rigid solutions (consecutive
/// entries of rigid, increasing in y, all at yaw; a jump: the point moves by more than 1 mm in s),
/// each located by bisection and its band found by following the other branch past it at the
/// rigid pose until the two touching heights differ by h (or it folds away, which bounds h). A
/// jump whose other branch vanishes within one trace_step on either side (a fold jump, as onto
/// S1002's flange) has a transition narrower than the walk resolves and gets no band.
/// @throws std::runtime_error from the rigid solver when a pose in a band has no contact.
std::vector<JumpTransition> find_jump_transitions(const RigidWheelsetSolver& solver,
                                                  const std::vector<RigidContact>& rigid, double yaw,
                                                  const JumpTransitionOptions& options);

}  // namespace wrc
