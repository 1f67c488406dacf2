// SPDX-License-Identifier: Apache-2.0
// The grid of `wrc sweep`: KEY=VALUES parsing (lists, FROM:TO:STEP ranges, values of their own),
// the Cartesian product's order and index, and the errors naming the bad text.
#include <gtest/gtest.h>

#include <limits>

#include "cli/sweep/sweep_grid.hpp"
#include "unit/expect_invalid.hpp"

namespace wrc::sweep {
namespace {

using Values = std::vector<std::string>;

TEST(SweepGrid, ListsRangesAndMixedItems) {
  EXPECT_EQ(parse_grid_axis("friction=0.2,0.3,0.4").values, (Values{"0.2", "0.3", "0.4"}));
  EXPECT_EQ(parse_grid_axis("speed=10:40:10").values, (Values{"10", "20", "30", "40"}));
  EXPECT_EQ(parse_grid_axis("speed=10:30:10,35").values, (Values{"10", "20", "30", "35"}));
  // Rounding of the steps: 0.1 * 3 is 0.30000000000000004 in doubles, written 0.3.
  EXPECT_EQ(parse_grid_axis("y0=0.1:0.3:0.1").values, (Values{"0.1", "0.2", "0.3"}));
  // The end is included within rounding, and a step past it stops before it.
  EXPECT_EQ(parse_grid_axis("y0=0:1:0.25").values, (Values{"0", "0.25", "0.5", "0.75", "1"}));
  EXPECT_EQ(parse_grid_axis("y0=0:1:0.3").values, (Values{"0", "0.3", "0.6", "0.9"}));
  EXPECT_EQ(parse_grid_axis("y0=-0.002:0.002:0.002").values, (Values{"-0.002", "0", "0.002"}));
  EXPECT_EQ(parse_grid_axis("speed=5:5:1").values, (Values{"5"}));
}

TEST(SweepGrid, ItemsThatAreNoRangeAreValuesOfTheirOwn) {
  // Two parts, or words: a profile name, an inclination, a file.
  EXPECT_EQ(parse_grid_axis("wheel=conic:0.025,conic:0.05,S1002").values, (Values{"conic:0.025", "conic:0.05", "S1002"}));
  EXPECT_EQ(parse_grid_axis("inclination=1:40,1:20,none").values, (Values{"1:40", "1:20", "none"}));
  EXPECT_EQ(parse_grid_axis("wheel=profiles/a.txt").values, (Values{"profiles/a.txt"}));
  EXPECT_EQ(parse_grid_axis("rail=a:b:c").values, (Values{"a:b:c"}));
}

TEST(SweepGrid, KeysTakeOptionSpelling) {
  EXPECT_EQ(parse_grid_axis("vertical-force=1,2").key, "vertical_force");
  EXPECT_EQ(parse_grid_axis("vertical_force=1,2").key, "vertical_force");
}

TEST(SweepGrid, BadTextIsNamed) {
  test::expect_invalid([] { parse_grid_axis("speed"); }, {"'speed'", "KEY=VALUES"});
  test::expect_invalid([] { parse_grid_axis("=1,2"); }, "KEY=VALUES");
  test::expect_invalid([] { parse_grid_axis("speed="); }, "no values");
  test::expect_invalid([] { parse_grid_axis("speed=1,,2"); }, "empty value");
  test::expect_invalid([] { parse_grid_axis("speed=1,2,"); }, "empty value");
  test::expect_invalid([] { parse_grid_axis(",speed=1"); }, "letters, digits");
  test::expect_invalid([] { parse_grid_axis("speed=10,20,10"); }, {"10", "twice"});
  test::expect_invalid([] { parse_grid_axis("speed=10:30:10,20"); }, {"20", "twice"});
  test::expect_invalid([] { parse_grid_axis("speed=40:10:10"); }, {"40:10:10", "TO is below FROM"});
  test::expect_invalid([] { parse_grid_axis("speed=10:40:0"); }, {"10:40:0", "step must be positive"});
  test::expect_invalid([] { parse_grid_axis("speed=10:40:-5"); }, "step must be positive");
  test::expect_invalid([] { parse_grid_axis("speed=0:1:1e-6"); }, {"more than", "10000"});
  test::expect_invalid([] { range_values(0, std::numeric_limits<double>::infinity(), 1); }, "finite");
}

TEST(SweepGrid, ProductOrderFirstKeySlowest) {
  const Grid grid({parse_grid_axis("speed=10,20,30"), parse_grid_axis("friction=0.2,0.3")});
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid.point(0), (Values{"10", "0.2"}));
  EXPECT_EQ(grid.point(1), (Values{"10", "0.3"}));
  EXPECT_EQ(grid.point(2), (Values{"20", "0.2"}));
  EXPECT_EQ(grid.point(5), (Values{"30", "0.3"}));
  for (std::size_t i = 0; i < grid.size(); ++i) EXPECT_EQ(grid.index_of(grid.point(i)), i);
  EXPECT_EQ(grid.index_of({"25", "0.2"}), grid.size());
  EXPECT_EQ(grid.index_of({"10"}), grid.size());
  EXPECT_THROW(grid.point(6), std::out_of_range);
}

TEST(SweepGrid, GridRules) {
  test::expect_invalid([] { Grid(std::vector<GridAxis>{}); }, "at least one --grid");
  test::expect_invalid([] { Grid({parse_grid_axis("speed=1,2"), parse_grid_axis("speed=3")}); }, {"speed", "twice"});
  test::expect_invalid([] { Grid({GridAxis{"speed", {}}}); }, "no values");
  test::expect_invalid(
      [] {
        Grid({parse_grid_axis("a=1:1000:1"), parse_grid_axis("b=1:1000:1")});
      },
      {"1000000 runs", "100000"});
}

}  // namespace
}  // namespace wrc::sweep
