// SPDX-License-Identifier: Apache-2.0
// The inclusive FROM:TO:STEP rule (core/numerics/inclusive_range.hpp) as the front end's options
// use it: --speeds (speed_scan_option.hpp), --critical-speeds (sweep_results.hpp) and --grid MxN
// (grid_option.hpp). Decimal steps keep their last value, bad text is refused naming the option.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/grid_option.hpp"
#include "cli/speed_scan_option.hpp"
#include "cli/sweep/sweep_results.hpp"
#include "core/numerics/inclusive_range.hpp"

namespace wrc::cli {
namespace {

TEST(Ranges, DecimalStepsKeepTheirLastValue) {
  // 0.3 - 0.1 = 0.19999999999999998 and 0.2 / 0.1 rounds below 2: still three values.
  const std::vector<double> v = parse_speed_scan("0.1:0.3:0.1", "--speeds");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v.front(), 0.1);
  EXPECT_NEAR(v.back(), 0.3, 1e-15);
  EXPECT_LE(v.back(), 0.3);
  EXPECT_EQ(parse_speed_scan("5:80:1", "--speeds").size(), 76u);
  EXPECT_EQ(parse_speed_scan("5:5:1", "--speeds").size(), 1u);
  EXPECT_EQ(inclusive_range_count(0.0, 1.0, 0.3), 4);  // 0, 0.3, 0.6, 0.9: 1 is not reached
  EXPECT_EQ(critical_speed_scan("40:60:10"), (std::vector<double>{40, 50, 60}));
}

TEST(Ranges, BadRangesNameTheOption) {
  for (const std::string text : {"5:80", "80:5:1", "5:80:0", "5:x:1", "5:80:1:2"}) {
    try {
      parse_speed_scan(text, "--speeds");
      ADD_FAILURE() << "accepted " << text;
    } catch (const UsageError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--speeds", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(inclusive_range_count(0.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(inclusive_range_count(0.0, NAN, 1.0), std::invalid_argument);
}

TEST(Ranges, FastsimGrid) {
  const FastsimGrid g = parse_grid("20x30", 1, 100);
  EXPECT_EQ(g.elements_per_strip, 20);
  EXPECT_EQ(g.strips, 30);
  EXPECT_EQ(parse_grid("5X5", 1, 100).strips, 5);
  for (const std::string text : {"20", "20x", "0x5", "20x200", "2.5x4", "axb"}) {
    try {
      parse_grid(text, 1, 100);
      ADD_FAILURE() << "accepted " << text;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--grid: '" + text + "'"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace wrc::cli
