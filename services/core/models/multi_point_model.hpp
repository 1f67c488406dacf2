// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Hertzian multi-point contact (Arnold, section 3; [JS94]): a Hertz ellipse at every potential
/// common point that is a local minimum of the distance, the normal force divided elastically.

#include <memory>

#include "core/models/hertzian_model.hpp"

namespace wrc {

/// Model "multipoint". Per wheel, every local minimum of the distance along the curve C at the
/// query pose (exact geometry, one potential-point scan per wheel, which also gives the maxima
/// between the minima):
///  - kElastic: each minimum's depth below the overlap level 0, depth_k = -distance_k where its
///    overlap is separate from the others', shared where minima lie in one connected overlap
///    (region_depths(), interpenetration_regions.hpp), gives delta_k = depth_k cos(angle_k) and
///    N_k = C_H,k delta_k^{3/2}; minima with delta_k <= 0 get no patch;
///  - kRigid: the wheel's normal_load is divided by divide_load(): a common vertical approach d of
///    the rigid wheel (the level, above the lowest minimum), delta_k = depth_k(d) cos(angle_k) by
///    the same rule, d chosen so that the normal forces sum to the load (the one-point model's
///    meaning of the load). Minima not reached (delta_k <= 0) get no patch; penetration is
///    reported as 0 (kRigid convention).
/// Both are continuous where a minimum is born or vanishes at a fold of the distance (it starts
/// with depth 0) and where two minima of one overlap pass each other.
/// A wheel without a minimum, or whose smallest minimum shows a climbed flange (flange_climb.hpp), throws ContactConfigurationError as in OnePointModel.
/// With a single minimum, or a single reached minimum, the result is identical to OnePointModel's.
/// Patches of one wheel are ordered by s (flange first), left wheel first.
class MultiPointModel final : public HertzianContactModel {
 public:
  /// @throws std::invalid_argument for a null geometry or invalid options.
  explicit MultiPointModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options = {});

  std::string name() const override { return "multipoint"; }

 private:
  WheelConstraint add_wheel_patches(WheelSide side, const PatchContext& context,
                                    ContactResult& result) const override;
};

}  // namespace wrc
