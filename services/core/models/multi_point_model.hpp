#pragma once
/// @file
/// Hertzian multi-point contact (Arnold, section 3; [JS94]): a Hertz ellipse at every potential
/// common point that is a local minimum of the distance, the normal force divided elastically.

#include <memory>

#include "core/models/hertzian_model.hpp"

namespace wrc {

/// Model "multipoint". Per wheel, every local minimum of the distance along the curve C at the
/// query pose (exact geometry, one potential-point scan per wheel):
///  - kElastic: each minimum's own penetration delta_k = -distance_k cos(angle_k) gives
///    N_k = C_H,k delta_k^{3/2}; minima with delta_k <= 0 get no patch;
///  - kRigid: the wheel's normal_load is divided by divide_load(): a common vertical approach d of
///    the rigid wheel, delta_k = (d - (distance_k - distance_min)) cos(angle_k), chosen so that
///    the normal forces sum to the load (the one-point model's meaning of the load). Minima not
///    reached (delta_k <= 0) get no patch; penetration is reported as 0 (kRigid convention).
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
