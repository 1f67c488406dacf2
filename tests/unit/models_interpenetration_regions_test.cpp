// SPDX-License-Identifier: Apache-2.0
// The sharing of a wheel's approach among minima of one connected overlap
// (interpenetration_regions.hpp): separate regions keep their full depth, the deepest minimum always
// keeps its own, a minimum born at a fold starts from 0, and the depths are continuous where the
// rule changes its case (birth, separation, two minima passing each other, equal maxima; not at a
// flat region, where a birth and a crossing coincide) and never exceed a minimum's own depth below
// the level.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/models/interpenetration_regions.hpp"

namespace wrc {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One minimum: its depth below the level, or 0 above it.
TEST(ModelsInterpenetrationRegions, OneMinimumHasItsDepth) {
  EXPECT_DOUBLE_EQ(region_depths({{-80e-6}}, 0.0)[0], 80e-6);
  EXPECT_EQ(region_depths({{15e-6}}, 0.0)[0], 0.0);
  EXPECT_TRUE(region_depths({}, 0.0).empty());
}

// A barrier at or above the level separates: both minima keep level - distance (the paper's
// multi-point rule), exactly.
TEST(ModelsInterpenetrationRegions, SeparateRegionsKeepTheirDepths) {
  const std::vector<double> d = region_depths({{-100e-6, 20e-6}, {-40e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(d[0], 100e-6);
  EXPECT_DOUBLE_EQ(d[1], 40e-6);
  const std::vector<double> touching = region_depths({{-100e-6, 0.0}, {-40e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(touching[1], 40e-6);
}

// One region: the deepest keeps its full depth, the other its depth below the barrier scaled by
// the region's depth over the deepest's depth below the barrier (hand computation: level 0,
// minima -100 and -60 um, barrier -50 um: 100 um and 10 um x 100 / 50 = 20 um).
TEST(ModelsInterpenetrationRegions, MergedRegionSharesTheDepth) {
  const std::vector<double> d = region_depths({{-100e-6, -50e-6}, {-60e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(d[0], 100e-6);
  EXPECT_NEAR(d[1], 20e-6, 1e-18);
  EXPECT_LT(d[1], 60e-6);  // less than its own depth below the level
}

// Continuity where the case changes, each checked from both sides with a step of 1e-12 m:
// birth at a fold (barrier -> the minimum), separation (barrier -> level), and two minima passing
// each other inside one region. Depths are O(1e-4 m) and Lipschitz with a constant of order
// level / (barrier - deepest) <= 10 here, so a step of 1e-12 m moves them by less than 1e-10 m.
TEST(ModelsInterpenetrationRegions, ContinuousWhereTheRuleChangesCase) {
  auto close = [](const std::vector<double>& a, const std::vector<double>& b) {
    for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-10) << "minimum " << k;
  };
  const double e = 1e-12;
  // Birth: the second minimum merges with its barrier (-90 um) and has depth 0.
  const std::vector<double> born = region_depths({{-100e-6, -90e-6}, {-90e-6}}, 0.0);
  EXPECT_EQ(born[1], 0.0);
  EXPECT_DOUBLE_EQ(born[0], 100e-6);
  close(born, region_depths({{-100e-6, -90e-6 + e}, {-90e-6}}, 0.0));
  // Separation: barrier at the level.
  close(region_depths({{-100e-6, -e}, {-60e-6}}, 0.0), region_depths({{-100e-6, e}, {-60e-6}}, 0.0));
  // Passing: equal minima in one region get equal depths, from either side.
  const std::vector<double> tie = region_depths({{-80e-6, -30e-6}, {-80e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(tie[0], 80e-6);
  EXPECT_DOUBLE_EQ(tie[1], 80e-6);
  close(tie, region_depths({{-80e-6 - e, -30e-6}, {-80e-6}}, 0.0));
  close(tie, region_depths({{-80e-6, -30e-6}, {-80e-6 - e}}, 0.0));
}

// Three minima with two equal barriers: the result does not depend on which is split first
// (checked by perturbing either barrier by 1e-12 m), and each minimum's depth is the region's
// scaled by its depth below the common barrier.
TEST(ModelsInterpenetrationRegions, EqualBarriersGiveOneAnswer) {
  const double e = 1e-12;
  const std::vector<double> tie = region_depths({{-100e-6, -40e-6}, {-70e-6, -40e-6}, {-50e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(tie[0], 100e-6);
  EXPECT_NEAR(tie[1], 100e-6 * 30.0 / 60.0, 1e-18);
  EXPECT_NEAR(tie[2], 100e-6 * 10.0 / 60.0, 1e-18);
  for (const auto& other : {region_depths({{-100e-6, -40e-6 + e}, {-70e-6, -40e-6}, {-50e-6}}, 0.0),
                            region_depths({{-100e-6, -40e-6}, {-70e-6, -40e-6 + e}, {-50e-6}}, 0.0)})
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(other[k], tie[k], 1e-10) << "minimum " << k;
}

// The one discontinuity (interpenetration_regions.hpp): two minima and the barrier between them at
// one height. There both have the full depth (the region has no height, region_height == 0); a
// minimum 1e-12 m lower than the other makes the other a minimum just born, with depth 0.
TEST(ModelsInterpenetrationRegions, FlatRegionIsTheOneDiscontinuity) {
  const std::vector<double> flat = region_depths({{-90e-6, -90e-6}, {-90e-6}}, 0.0);
  EXPECT_DOUBLE_EQ(flat[0], 90e-6);
  EXPECT_DOUBLE_EQ(flat[1], 90e-6);
  const std::vector<double> tilted = region_depths({{-90e-6 - 1e-12, -90e-6}, {-90e-6}}, 0.0);
  EXPECT_NEAR(tilted[0], 90e-6, 1e-11);
  EXPECT_EQ(tilted[1], 0.0);
}

// Over random chains of up to four minima and random levels: every depth is in [0, level -
// distance], the deepest reaching minimum has exactly level - distance, and the depths do not
// decrease when the level rises.
TEST(ModelsInterpenetrationRegions, BoundsAndMonotoneInTheLevel) {
  unsigned state = 12345;
  auto uniform = [&state] {
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xffffff) / static_cast<double>(0x1000000);
  };
  for (int trial = 0; trial < 2000; ++trial) {
    const size_t n = 1 + static_cast<size_t>(uniform() * 4) % 4;
    std::vector<DistanceMinimum> chain(n);
    for (auto& m : chain) m.distance = -200e-6 + 300e-6 * uniform();
    for (size_t k = 0; k + 1 < n; ++k)
      chain[k].barrier_after = std::max(chain[k].distance, chain[k + 1].distance) + 150e-6 * uniform();
    const double level = -50e-6 + 100e-6 * uniform();
    const std::vector<double> d = region_depths(chain, level);
    const std::vector<double> higher = region_depths(chain, level + 1e-6);
    size_t deepest = 0;
    for (size_t k = 0; k < n; ++k) {
      if (chain[k].distance < chain[deepest].distance) deepest = k;
      EXPECT_GE(d[k], 0.0);
      EXPECT_LE(d[k], std::max(0.0, level - chain[k].distance) * (1 + 1e-12) + 1e-18) << "trial " << trial;
      EXPECT_GE(higher[k], d[k] - 1e-18) << "trial " << trial;
    }
    EXPECT_NEAR(d[deepest], std::max(0.0, level - chain[deepest].distance), 1e-18) << "trial " << trial;
  }
}

// Bad input names the value.
TEST(ModelsInterpenetrationRegions, BadInputThrows) {
  EXPECT_THROW(region_depths({{-1e-6}}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(region_depths({{std::nan("")}}, 0.0), std::invalid_argument);
  EXPECT_THROW(region_depths({{-1e-6, -5e-6}, {-2e-6}}, 0.0), std::invalid_argument);  // barrier below a minimum
  try {
    region_depths({{-1e-6, -5e-6}, {-2e-6}}, 0.0);
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("barrier_after = -5e-06"), std::string::npos) << error.what();
  }
  EXPECT_NO_THROW(region_depths({{-1e-6, kInf}, {-2e-6}}, 0.0));
}

}  // namespace
}  // namespace wrc
