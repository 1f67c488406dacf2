// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// How the approach of a wheel is shared among the local minima of its distance that lie in one
/// connected interpenetration region (the Hertzian multi-point model's rule, multi_point_model.hpp).
///
/// Why: along the curve C (the lowest points of the wheel, one per profile coordinate s) the
/// vertical distance has local minima separated by local maxima. The multi-point model puts a Hertz
/// patch at every minimum. Where a maximum between two minima lies below the level to which the
/// surfaces overlap, the two minima are one connected overlap, and giving each its full depth below
/// that level counts the overlap between them twice. Worse, a minimum appears and disappears with
/// its neighbouring maximum at a fold of the distance (S1002 on UIC60 in the centred position:
/// the minima at s = 3.2 mm and -7.4 mm are 8.5 um apart in height, the maximum between them 1.4 um
/// above the higher one, under about 100 um of overlap), so a
/// patch with the full depth would be born or vanish at once, and near the fold the relative
/// curvature goes to zero and its Hertz stiffness grows without bound: measured, a jump of 470 kN of
/// normal force at the fold near y = 0.501 mm at a fixed height.
///
/// The rule: a minimum whose region is separated from the others (every maximum between them at
/// or above the level) keeps its full depth below the level. In one connected region the deepest
/// minimum keeps its full depth, and the region is split at its highest interior maximum c; a part
/// whose deepest minimum lies h_part below c receives the depth (level - d_deepest) h_part /
/// h_region of the region's deepest point (h_region = c - d_deepest), and is then treated the same
/// way, recursively. So a minimum's depth is its region's depth scaled by how far it lies below the
/// maximum that joins it to the deeper part:
///  - continuous in every distance and in the level: 0 when a minimum is born at a fold (h = 0),
///    the full depth when the maximum rises to the level (the regions separate), equal depths when
///    two minima in one region pass each other, and independent of the order in which equal maxima
///    are split. One exception, which no rule that keeps the deepest minimum's full depth avoids:
///    where two minima and the maximum between them lie at one height (a birth and a crossing at
///    once), the depth of the other minimum jumps between 0 and the full depth (there both get the
///    full depth); a flat stretch of the distance, which profiles do not have in practice;
///  - never more than the minimum's own depth below the level, non-decreasing in the level, and
///    the deepest minimum always has its full depth (so the force still grows with the approach).
/// It is a regularisation of the multi-Hertzian idealisation, not a contact theory: where minima
/// merge, the real patch is one non-elliptic conformal contact that a Hertz patch per minimum does
/// not describe (docs/contact-mechanics.md).

#include <limits>
#include <vector>

namespace wrc {

/// One local minimum of a wheel's vertical distance along the curve C, in order of s.
struct DistanceMinimum {
  double distance = 0;  ///< vertical distance at the minimum [m] (any common reference)
  /// The highest vertical distance between this minimum and the next one along C [m] (the local
  /// maximum separating them; same reference); +infinity for the last minimum, or where the
  /// maximum is not known (the two are then treated as separate regions).
  double barrier_after = std::numeric_limits<double>::infinity();
};

/// Checks a chain of minima as region_depths() needs it: finite distances, and every barrier (but
/// the last one's) not NaN and not below the two minima it separates.
/// @throws std::invalid_argument whose message starts with who and names the minimum and values.
void check_distance_minima(const std::vector<DistanceMinimum>& minima, const char* who);

/// The vertical depth of every minimum below level [m] (same reference as the distances; points
/// with a distance below level overlap) after the sharing rule above: >= 0, at most level -
/// distance, 0 where the minimum does not reach the level.
/// @throws std::invalid_argument naming the value when a distance or level is not finite, or a
///         barrier lies below one of the two minima it separates.
std::vector<double> region_depths(const std::vector<DistanceMinimum>& minima, double level);

}  // namespace wrc
