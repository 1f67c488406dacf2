// SPDX-License-Identifier: Apache-2.0
#include "core/models/multi_point_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/contact/hertz.hpp"
#include "core/geometry/potential_points.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/model_interface/wheelset_motion.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/interpenetration_regions.hpp"
#include "core/models/load_division.hpp"
#include "core/models/one_point_model.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {

MultiPointModel::MultiPointModel(std::shared_ptr<const WheelsetGeometry> geometry, ContactModelOptions options)
    : HertzianContactModel(std::move(geometry), options, "MultiPointModel") {}

WheelConstraint MultiPointModel::add_wheel_patches(WheelSide side, const PatchContext& context,
                                                   ContactResult& result) const {
  const double floor = options_.lateral_curvature_floor;
  const ContactQuery& query = context.query;
  // The minima along C, and the highest point between each and the next (the regions' barriers).
  std::vector<ContactPoint> minima;
  std::vector<double> barrier_after;
  for (ContactPoint& p : geometry_->potential_points(side, query.pose, options_.search)) {
    if (p.is_minimum) {
      minima.push_back(std::move(p));
      barrier_after.push_back(std::numeric_limits<double>::infinity());
    } else if (!minima.empty()) {
      double& barrier = barrier_after.back();
      barrier = std::isinf(barrier) ? p.distance : std::max(barrier, p.distance);
    }
  }
  if (!minima.empty()) barrier_after.back() = std::numeric_limits<double>::infinity();
  // No maximum listed between two minima (a root pair closer than the search's tolerance, or a
  // maximum at a slope jump): the barrier is searched for, so that a missed maximum cannot turn one
  // overlap into two with full depths; where C leaves the rail between them they are separate.
  for (size_t k = 0; k + 1 < minima.size(); ++k) {
    if (!std::isinf(barrier_after[k])) continue;
    const double top = highest_distance_between(geometry_->locus(side, query.pose), minima[k].s, minima[k + 1].s);
    if (!std::isnan(top)) barrier_after[k] = top;
  }
  size_t closest = 0;
  for (size_t k = 1; k < minima.size(); ++k)
    if (minima[k].distance < minima[closest].distance) closest = k;
  check_common_point(*geometry_, side, minima.empty() ? nullptr : &minima[closest], query.pose, steepest_flange_);
  // Every minimum carries its own force, so nothing jumps: the constraint is the lowest point's.
  const WheelConstraint constraint =
      exact_point_constraint(minima[closest], query.pose, kNoSwitch, std::numeric_limits<double>::quiet_NaN());
  // A maximum is never below the minima beside it; a root found to 1e-12 m in s may be by rounding.
  auto barrier_of = [&](size_t k) {
    return k + 1 < minima.size() ? std::max({barrier_after[k], minima[k].distance, minima[k + 1].distance})
                                 : barrier_after[k];
  };
  if (query.formulation == ContactFormulation::kElastic) {
    std::vector<DistanceMinimum> chain;
    for (size_t k = 0; k < minima.size(); ++k) chain.push_back({minima[k].distance, barrier_of(k)});
    const std::vector<double> depth = region_depths(chain, 0.0);
    for (size_t k = 0; k < minima.size(); ++k) {
      const double delta = depth[k] * std::cos(minima[k].contact_angle);
      if (delta > 0.0)
        result.patches.push_back(patch_from_penetration(minima[k], contact_shape(minima[k], floor), delta, context));
    }
    return constraint;
  }
  const double load = query.normal_load[static_cast<int>(side)];
  if (!(load > 0.0)) return constraint;
  // The closest minimum alone carrying the load bounds the approach: minima farther away than
  // that cannot be reached and need no Hertz shape (their curvatures may not even be Hertzian).
  // Leaving one out joins the barriers on either side (the higher of them), which leaves every
  // other point's depth unchanged: the minimum lies above every level the division tries.
  const PatchShape closest_shape = contact_shape(minima[closest], floor);
  const double closest_cos = std::cos(minima[closest].contact_angle);
  const double reach = std::pow(load / hertz_stiffness(closest_shape.shape, context.contact_modulus), 2.0 / 3.0) /
                       closest_cos;
  const double lowest = minima[closest].distance;
  std::vector<PatchShape> shapes;
  std::vector<DivisionPoint> division;
  std::vector<size_t> index;
  for (size_t k = 0; k < minima.size(); ++k) {
    const double gap = minima[k].distance - lowest;
    if (k != closest && !(gap < reach)) {
      if (!division.empty()) {
        double& joined = division.back().barrier_after;
        joined = std::max(joined, barrier_of(k) - lowest);
      }
      continue;
    }
    shapes.push_back(k == closest ? closest_shape : contact_shape(minima[k], floor));
    division.push_back({hertz_stiffness(shapes.back().shape, context.contact_modulus), gap,
                        std::cos(minima[k].contact_angle), barrier_of(k) - lowest});
    index.push_back(k);
  }
  if (!division.empty()) division.back().barrier_after = std::numeric_limits<double>::infinity();
  const LoadDivision split = divide_load(load, division);
  for (size_t j = 0; j < index.size(); ++j) {
    if (split.normal_force[j] > 0.0)
      result.patches.push_back(patch_from_force(minima[index[j]], shapes[j], split.normal_force[j], context));
  }
  return constraint;
}

}  // namespace wrc
