#include "core/models/interpolated_model.hpp"

#include <chrono>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/models/patch_builder.hpp"

namespace wrc {
namespace {

// Builds the table and records how long it took.
ContactPointTable timed_table(const WheelsetGeometry& geometry, const ContactModelOptions& options, double& seconds) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  ContactPointTable table(geometry, options.interp, options.search);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return table;
}

}  // namespace

InterpolatedModel::InterpolatedModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : HertzianContactModel(std::move(geometry), options, "InterpolatedModel"),
      table_(timed_table(*geometry_, options_, precomputation_seconds_)) {}

void InterpolatedModel::add_wheel_patches(WheelSide side, const PatchContext& context, ContactResult& result) const {
  std::optional<ContactPatch> patch =
      one_point_patch(table_.at(side, context.query.pose), context, options_.lateral_curvature_floor);
  if (patch) result.patches.push_back(std::move(*patch));
}

}  // namespace wrc
