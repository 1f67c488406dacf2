// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Arnold's unified approach (section 4) as a contact model: the contact point, the vertical
/// displacement and every Hertz and FASTSIM input from the fitted splines, one ellipse per wheel
/// with the fitted shape and the contact point as centre.

#include <memory>
#include <vector>

#include "core/models/hertzian_model.hpp"
#include "core/spline/spline_contact_geometry.hpp"

namespace wrc {

/// Model "spline". Per wheel at the query pose:
///  - outside the wheel's spline box: OutsideModelError naming the coordinate and the box;
///  - flange clearance > 0 (tread and flange root, where the exact common point's jumps are
///    artefacts of the rigid one-point view): the fitted contact point, distance z - z_touch and
///    Hertz shape; the patch as in OnePointModel (kRigid: from the wheel's load; kElastic: from
///    the penetration -distance cos(angle)). Only the fields a patch needs are evaluated
///    (kSplineQueryFieldCount): the patch's contact point has NaN theta, rolling-direction
///    curvatures and distance_curvature (SplineContactGeometry::evaluate of every field gives them);
///  - flange clearance <= 0 (flange contact, a physical discontinuity the model keeps): the exact
///    common point and its Hertz shape, as OnePointModel. The fitted clearance is continuous, so
///    a simulation locates the switch as the root of that function (an event). Where it is <= 0
///    but the exact geometry has no minimum on the flange side (the fit's error near the flange
///    root), the tread stays: its switch function is mirrored above 0 there, and jumps to the
///    clearance where the exact flange minimum appears (the event is then that jump).
class SplineModel final : public HertzianContactModel {
 public:
  /// @throws std::invalid_argument for a null geometry or splines, or invalid options.
  SplineModel(std::shared_ptr<const WheelsetGeometry> geometry, std::shared_ptr<const SplineContactGeometry> splines,
              ContactModelOptions options = {});

  std::string name() const override { return "spline"; }
  const SplineContactGeometry& splines() const { return *splines_; }

 private:
  WheelConstraint add_wheel_patches(WheelSide side, const PatchContext& context,
                                    ContactResult& result) const override;
  /// Whether one of points is a minimum of the distance on the flange side of the splines' split.
  bool any_flange_side_minimum(const std::vector<ContactPoint>& points) const;
  /// Whether the exact geometry of wheel side has such a minimum at pose.
  bool has_flange_side_minimum(WheelSide side, const WheelsetPose& pose) const;
  std::shared_ptr<const SplineContactGeometry> splines_;
};

}  // namespace wrc
