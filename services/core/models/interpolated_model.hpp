// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Interpolated Hertzian contact as in MEDYNA (Arnold, section 3): Hertzian one-point contact at a
/// set of interpolation configurations, its parameters interpolated in between.

#include <memory>

#include "core/models/contact_point_table.hpp"
#include "core/models/hertzian_model.hpp"

namespace wrc {

/// Model "interp". The constructor tabulates the rigid wheelset and the exact common point of each
/// wheel on the grid options.interp (ContactPointTable: nodes in y and yaw, a few roll nodes about
/// the rigid roll); evaluate() interpolates contact point, normal, angle, radius, distance and
/// curvatures there (no geometry scan) and builds one Hertz patch per wheel exactly as
/// OnePointModel does (same rigid and elastic rules, same curvature floor). The gap is the
/// interpolated distance, C1, with its exact gradient; its rigid solution (both gaps 0) is the
/// interpolated rigid wheelset, exact at the nodes. The interpolation is continuous in the
/// configuration: a jump of the common point is smoothed over the band in which an elastic
/// contact loads both points (a folded jump over one y cell), and within a band the wheel
/// touches at both points, two patches (add_shared_patches()); away from the bands, at the
/// nodes, the model reproduces OnePointModel. A configuration outside the table throws
/// OutsideModelError naming the coordinate.
class InterpolatedModel final : public HertzianContactModel {
 public:
  /// Builds the table (y_points yaw_points rigid solves and 2 y_points roll_points yaw_points
  /// common points; its time: BM_InterpPrecompute, tests/bench/models_bench.cpp).
  /// @throws std::invalid_argument for a null geometry or invalid options; ContactConfigurationError
  ///         when a node of the table has no contact.
  explicit InterpolatedModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options = {});

  std::string name() const override { return "interp"; }
  /// The interpolation table.
  const ContactPointTable& table() const { return table_; }
  /// Wall time the constructor spent building the table [s].
  double precomputation_seconds() const { return precomputation_seconds_; }

 private:
  WheelConstraint add_wheel_patches(WheelSide side, const PatchContext& context,
                                    ContactResult& result) const override;
  double precomputation_seconds_ = 0;
  ContactPointTable table_;
};

}  // namespace wrc
