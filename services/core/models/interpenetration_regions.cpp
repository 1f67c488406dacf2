// SPDX-License-Identifier: Apache-2.0
#include "core/models/interpenetration_regions.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

// Depths of minima[first..last] (one stretch of C) at level.
void assign_depths(const std::vector<DistanceMinimum>& minima, size_t first, size_t last, double level,
                   std::vector<double>& depth) {
  double deepest = minima[first].distance;
  for (size_t k = first + 1; k <= last; ++k) deepest = std::min(deepest, minima[k].distance);
  if (!(level > deepest)) return;  // nothing of this stretch reaches the level
  if (first == last) {
    depth[first] = level - deepest;
    return;
  }
  double highest = -std::numeric_limits<double>::infinity();
  for (size_t k = first; k < last; ++k) highest = std::max(highest, minima[k].barrier_after);
  // Separate regions: split at every maximum that reaches the level, each part keeps the level.
  // One region: split at its highest maximum(s); each part's level makes its deepest minimum's
  // depth the region's depth scaled by (highest - part's deepest) / (highest - region's deepest).
  const bool separate = highest >= level;
  const double split_at = separate ? level : highest;
  const double region_height = highest - deepest;
  size_t begin = first;
  for (size_t k = first; k <= last; ++k) {
    if (k < last && minima[k].barrier_after < split_at) continue;
    double part_deepest = minima[begin].distance;
    for (size_t j = begin + 1; j <= k; ++j) part_deepest = std::min(part_deepest, minima[j].distance);
    double part_level = level;
    if (!separate) {
      // region_height == 0 only when every minimum and maximum of the region lie at one height.
      const double share = region_height > 0 ? (highest - part_deepest) / region_height : 1.0;
      part_level = part_deepest + (level - deepest) * share;
    }
    assign_depths(minima, begin, k, part_level, depth);
    begin = k + 1;
  }
}

}  // namespace

void check_distance_minima(const std::vector<DistanceMinimum>& minima, const char* who) {
  for (size_t k = 0; k < minima.size(); ++k) {
    const DistanceMinimum& m = minima[k];
    const bool last = k + 1 == minima.size();
    const double next = last ? -std::numeric_limits<double>::infinity() : minima[k + 1].distance;
    if (!std::isfinite(m.distance) || std::isnan(m.barrier_after) ||
        (!last && !(m.barrier_after >= std::max(m.distance, next)))) {
      std::ostringstream msg;
      msg << who << ": minimum " << k << ": distance = " << m.distance << " m, barrier_after = " << m.barrier_after
          << " m (need finite distances and a barrier not below the two minima it separates)";
      throw std::invalid_argument(msg.str());
    }
  }
}

std::vector<double> region_depths(const std::vector<DistanceMinimum>& minima, double level) {
  if (!std::isfinite(level)) {
    std::ostringstream msg;
    msg << "region_depths: level = " << level << " m is not finite";
    throw std::invalid_argument(msg.str());
  }
  check_distance_minima(minima, "region_depths");
  std::vector<double> depth(minima.size(), 0.0);
  if (!minima.empty()) assign_depths(minima, 0, minima.size() - 1, level, depth);
  return depth;
}

}  // namespace wrc
