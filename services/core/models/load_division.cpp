// SPDX-License-Identifier: Apache-2.0
#include "core/models/load_division.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/models/interpenetration_regions.hpp"
#include "core/numerics/brent.hpp"

namespace wrc {

LoadDivision divide_load(double load, const std::vector<DivisionPoint>& points) {
  if (points.empty()) throw std::invalid_argument("divide_load: no contact points");
  if (!(load >= 0.0) || !std::isfinite(load)) {
    std::ostringstream msg;
    msg << "divide_load: load = " << load << " N must be non-negative and finite";
    throw std::invalid_argument(msg.str());
  }
  size_t closest = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    const DivisionPoint& p = points[k];
    if (!(p.stiffness > 0.0) || !std::isfinite(p.stiffness) || !(p.gap >= 0.0) || !std::isfinite(p.gap) ||
        !(p.cos_angle > 0.0) || !(p.cos_angle <= 1.0)) {
      std::ostringstream msg;
      msg << "divide_load: point " << k << ": stiffness = " << p.stiffness << " N/m^1.5, gap = " << p.gap
          << " m, cos(angle) = " << p.cos_angle << " (need stiffness > 0, gap >= 0, 0 < cos <= 1)";
      throw std::invalid_argument(msg.str());
    }
    if (p.gap < points[closest].gap) closest = k;
  }
  std::vector<DistanceMinimum> chain(points.size());
  for (size_t k = 0; k < points.size(); ++k) chain[k] = {points[k].gap, points[k].barrier_after};
  check_distance_minima(chain, "divide_load");  // also with no load to divide
  LoadDivision out;
  out.normal_force.assign(points.size(), 0.0);
  out.penetration.assign(points.size(), 0.0);
  if (load == 0.0) return out;

  auto penetrations = [&](double d) {
    std::vector<double> delta = region_depths(chain, d);
    for (size_t k = 0; k < points.size(); ++k) delta[k] *= points[k].cos_angle;
    return delta;
  };
  auto total = [&](double d) {
    double sum = 0;
    const std::vector<double> delta_at_d = penetrations(d);
    for (size_t k = 0; k < points.size(); ++k) {
      const double delta = delta_at_d[k];
      if (delta > 0) sum += points[k].stiffness * delta * std::sqrt(delta);
    }
    return sum;
  };
  const DivisionPoint& c = points[closest];
  const double d1 = c.gap + std::pow(load / c.stiffness, 2.0 / 3.0) / c.cos_angle;
  const double lo = c.gap;
  const RootResult root =
      brent_root([&](double d) { return total(d) - load; }, lo, d1, -load, total(d1) - load, 1e-14 * d1, 200);
  out.approach = require_converged(root, "load division: common approach for a load of " + std::to_string(load) + " N");

  double sum = 0;
  const std::vector<double> delta_at_approach = penetrations(out.approach);
  for (size_t k = 0; k < points.size(); ++k) {
    const double delta = delta_at_approach[k];
    if (delta > 0) {
      out.penetration[k] = delta;
      out.normal_force[k] = points[k].stiffness * delta * std::sqrt(delta);
      sum += out.normal_force[k];
      ++out.active;
    }
  }
  if (out.active == 1) {
    for (double& n : out.normal_force)
      if (n > 0) n = load;
  } else {
    const double scale = load / sum;
    for (double& n : out.normal_force) n *= scale;
  }
  return out;
}

}  // namespace wrc
