// SPDX-License-Identifier: Apache-2.0
#include "core/models/interpolated_model.hpp"

#include <array>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {
namespace {

// Builds the table and records how long it took.
ContactPointTable timed_table(const WheelsetGeometry& geometry, const ContactModelOptions& options, double& seconds) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  ContactPointTable table(geometry, options);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return table;
}

}  // namespace

InterpolatedModel::InterpolatedModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : HertzianContactModel(std::move(geometry), options, "InterpolatedModel"),
      table_(timed_table(*geometry_, options_, precomputation_seconds_)) {}

WheelConstraint InterpolatedModel::add_wheel_patches(WheelSide side, const PatchContext& context,
                                                     ContactResult& result) const {
  const TableContact contact = table_.evaluate(side, context.query.pose);
  std::optional<ContactPatch> patch = one_point_patch(contact.point, context, options_.lateral_curvature_floor);
  if (patch && contact.shared) {
    // Within a jump's band the wheel touches at both points (add_shared_patches()).
    std::array<SharedPoint, 2> parts;
    for (size_t b = 0; b < 2; ++b)
      parts[b] = {contact.branch_points[b], contact_shape(contact.branch_points[b], options_.lateral_curvature_floor),
                  contact.branch_shares[b], contact.branch_inclinations[b]};
    add_shared_patches(*patch, contact.inclination, parts, context, result);
    patch.reset();
  }
  if (patch) result.patches.push_back(std::move(*patch));
  // The interpolation is continuous: no jumps, no event. The gap gradient is the exact derivative
  // of the interpolated gap (C1), so the rigid-contact integrator's constraint and its gradient
  // agree.
  WheelConstraint c =
      exact_point_constraint(contact.point, context.query.pose, kNoSwitch, std::numeric_limits<double>::quiet_NaN());
  c.gap_gradient = contact.gap_gradient;
  return c;
}

}  // namespace wrc
