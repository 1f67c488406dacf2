// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Elastic division of a given wheel load among several Hertz contacts of one rigid wheel (the
/// rigid formulation of the Hertzian multi-point model).

#include <limits>
#include <vector>

namespace wrc {

/// One candidate contact of the wheel (a local minimum of its distance along the curve C).
struct DivisionPoint {
  double stiffness = 0;  ///< Hertz stiffness C_H of N = C_H delta^{3/2} [N/m^{3/2}], > 0
  double gap = 0;        ///< vertical distance above the smallest distance of the wheel [m], >= 0
  double cos_angle = 1;  ///< cosine of the contact angle [-], > 0
  /// The highest point of the distance between this point and the next one along C, above the
  /// smallest distance [m] (DistanceMinimum::barrier_after); +infinity: separate regions.
  double barrier_after = std::numeric_limits<double>::infinity();
};

/// The division found by divide_load().
struct LoadDivision {
  double approach = 0;               ///< common vertical approach d of the wheel [m]
  std::vector<double> normal_force;  ///< N_k per point [N] (0 for points not reached), sum = load
  std::vector<double> penetration;   ///< delta_k = depth_k(d) cos(angle_k) [m], 0 where not reached
  int active = 0;                    ///< points with N_k > 0
};

/// Divides load among the points as a rigid wheel pressed down vertically by d would: point k's
/// approach along its normal is delta_k = depth_k(d) cos(angle_k) (the vertical approach projected
/// on the normal, as normal_penetration()), where depth_k(d) is region_depths() of the points
/// (in order along C, with their barriers) at level d: d - gap_k for a point whose overlap is
/// separate from the others', less where overlaps merge (interpenetration_regions.hpp);
/// N_k = C_k (delta_k)_+^{3/2}, and d >= 0 is chosen so
/// that the NORMAL forces sum to the load, sum_k N_k = load (the same meaning of the load as in
/// the one-point model's rigid formulation: the normal force, not its vertical component).
/// sum_k N_k(d) is continuous and strictly increasing from 0 at d = 0 (the closest point has
/// gap 0 and always its full depth d), so d is bracketed by [0, d_1], d_1 the approach at which the closest point alone
/// carries the load, and found by Brent's method to 1e-14 d_1. The forces are then scaled by
/// load / sum (a factor 1 +- 1e-13) so that they sum to the load to rounding; a single active
/// point gets exactly the load.
/// @param load wheel load [N], >= 0 (0: every force 0).
/// @throws std::invalid_argument when points is empty, a stiffness or cosine is not positive, a
///         gap is negative, a value is not finite, or a barrier lies below a point it separates.
LoadDivision divide_load(double load, const std::vector<DivisionPoint>& points);

}  // namespace wrc
