#include "core/models/interpolated_model.hpp"

#include <chrono>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/models/patch_builder.hpp"
#include "core/models/query_validation.hpp"
#include "core/models/wheelset_motion.hpp"

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

std::shared_ptr<const WheelsetGeometry> InterpolatedModel::checked(std::shared_ptr<const WheelsetGeometry> geometry) {
  if (!geometry) throw std::invalid_argument("InterpolatedModel: no geometry");
  return geometry;
}

InterpolatedModel::InterpolatedModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : geometry_(checked(std::move(geometry))), options_(options),
      table_(timed_table(*geometry_, options_, precomputation_seconds_)) {}

ContactResult InterpolatedModel::evaluate(const ContactQuery& query) const {
  validate_contact_query(query);
  const WheelsetMotion motion = WheelsetMotion::from_query(query);
  const PatchContext context{query, motion, fastsim_.get(query.fastsim_elements, query.fastsim_strips),
                             contact_modulus(query.material.shear_modulus, query.material.poisson_ratio)};
  ContactResult result;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const ContactPoint point = table_.at(side, query.pose);
    std::optional<ContactPatch> patch = one_point_patch(point, context, options_.lateral_curvature_floor);
    if (patch) result.patches.push_back(std::move(*patch));
  }
  for (const ContactPatch& patch : result.patches) add_to_resultant(patch, motion.centre, result);
  return result;
}

}  // namespace wrc
