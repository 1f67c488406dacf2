// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// All potential common points of one wheel: zeros of the derivative of the distance along C.

#include <optional>
#include <vector>

#include "core/geometry/contact_locus.hpp"
#include "core/geometry/contact_point.hpp"

namespace wrc {

/// Settings of the potential-point search.
struct PotentialPointSearch {
  /// Largest sampling step along the wheel profile coordinate [m]. With profile envelopes (loci
  /// made by WheelsetGeometry) the step adapts: from a sample with slope g it advances by
  /// |g| / max|d2 distance/ds2| (no root can lie closer), within [min_step, step]. Without
  /// envelopes the sampling is uniform with this step. Root pairs closer than one step are still
  /// found where d(distance)/ds has a local extremum between samples (tangency check).
  double step = 1e-3;
  /// Smallest adaptive step [m].
  double min_step = 1e-4;
  /// Absolute tolerance of each root in s [m].
  double tolerance = 1e-12;
};

/// Every potential common point of the wheel described by locus, ordered by s (flange first).
/// Local minima and maxima of the distance are both returned; is_minimum tells them apart.
std::vector<ContactPoint> find_potential_points(const ContactLocus& locus, const PotentialPointSearch& search = {});

/// The highest vertical distance of C between s0 and s1 [m] (s0 < s1; two neighbouring local minima,
/// where the search listed no maximum between them: a pair of roots closer than its tolerance, or a
/// maximum at a slope jump of a yawed wheel), found by a golden-section search; NaN when C leaves
/// the rail inside [s0, s1].
double highest_distance_between(const ContactLocus& locus, double s0, double s1);

/// The local minima of the distance along C whose distance is below level [m], and nothing else:
/// a certificate that no point of C lies lower. Much cheaper than find_potential_points where the
/// distance is well above the level, since a step may then span the whole stretch over which a
/// quadratic lower bound of the distance stays above the level.
std::vector<ContactPoint> find_minima_below(const ContactLocus& locus, double level,
                                            const PotentialPointSearch& search = {});

/// The potential point near s_guess [m], followed from a neighbouring configuration: a local
/// minimum of the distance is searched in a bracket grown around s_guess up to max_shift [m].
/// Returns the locus point there, or nothing when no minimum lies there any more.
std::optional<LocusPoint> track_minimum(const ContactLocus& locus, double s_guess, double max_shift = 5e-3,
                                          double tolerance = 1e-12);

/// The common point among potential points: the local minimum with the smallest distance; on a
/// tie (within tie_tolerance [m]) the one farthest from the flange (largest s). Nothing if
/// there is no local minimum.
std::optional<ContactPoint> select_common_point(const std::vector<ContactPoint>& points, double tie_tolerance = 1e-12);

/// All contact quantities at a point of C where d(distance)/ds = 0.
ContactPoint make_contact_point(const ContactLocus& locus, double s, bool is_minimum);

}  // namespace wrc
