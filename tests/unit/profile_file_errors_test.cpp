// SPDX-License-Identifier: Apache-2.0
// Every bad-input case of the profile readers gives a ProfileError naming the file, the line and
// the reason (files in tests/data/).
#include <gtest/gtest.h>

#include <string>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/profile/profile_file.hpp"

namespace wrc {
namespace {

std::string data(const std::string& name) { return std::string(WRC_TEST_DATA_DIR) + "/" + name; }

// Reads `file` as `side` and expects a ProfileError at `line` whose reason contains `reason`.
void expect_error(const std::string& file, ProfileSide side, int line, const std::string& reason) {
  try {
    read_profile_file(file, side);
    ADD_FAILURE() << file << ": no error";
  } catch (const ProfileError& e) {
    EXPECT_EQ(e.source(), file);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
}

TEST(ProfileFileErrors, TextFiles) {
  expect_error(data("bad_missing_value.txt"), ProfileSide::kWheel, 4, "missing value");
  expect_error(data("bad_non_numeric.csv"), ProfileSide::kWheel, 4, "non-numeric value 'abc'");
  expect_error(data("bad_nan.txt"), ProfileSide::kWheel, 4, "NaN");
  expect_error(data("bad_non_monotonic.txt"), ProfileSide::kWheel, 5, "not monotonic");
  expect_error(data("bad_duplicate.txt"), ProfileSide::kWheel, 4, "duplicate lateral");
  expect_error(data("bad_too_few.txt"), ProfileSide::kWheel, 0, "too few points: 3");
  expect_error(data("bad_units.txt"), ProfileSide::kWheel, 2, "unknown units 'inch'");
  expect_error(data("wheel_side.txt"), ProfileSide::kRail, 1, "wheel profile given as a rail");
  expect_error(data("does_not_exist.txt"), ProfileSide::kWheel, 0, "cannot open file");
}

TEST(ProfileFileErrors, SimpackFiles) {
  expect_error(data("bad_units.prr"), ProfileSide::kRail, 8, "unknown units 'furlong'");
  expect_error(data("bad_no_point_end.prr"), ProfileSide::kRail, 12, "missing point.end");
  // The spline section's "type" (original data file type) must not count as the profile type.
  expect_error(data("bad_no_type.prr"), ProfileSide::kRail, 0, "missing header type");
  expect_error(data("bad_point_value.prr"), ProfileSide::kRail, 11, "non-numeric value 'zero'");
  // The Manchester wheel file (type 1) asked for as a rail, and the rail file as a wheel.
  const std::string prw = std::string(WRC_PROFILES_DIR) + "/MBench_S1002_v3.prw";
  expect_error(prw, ProfileSide::kRail, 12, "SIMPACK type 1 (wheel profile) given as a rail");
  const std::string prr = std::string(WRC_PROFILES_DIR) + "/MBench_UIC60_v3.prr";
  expect_error(prr, ProfileSide::kWheel, 12, "SIMPACK type 0 (rail profile) given as a wheel");
}

TEST(ProfileFileErrors, MiniProfFiles) {
  expect_error(data("bad_columns.ban"), ProfileSide::kRail, 3, "unsupported ColumnDef 'Y,X'");
  expect_error(data("small_rail.ban"), ProfileSide::kWheel, 0, "rail profiles, asked for as a wheel");
}

// The factory passes file paths to the readers (same errors).
TEST(ProfileFileErrors, ThroughFactory) {
  EXPECT_THROW(make_profile(data("bad_nan.txt"), ProfileSide::kWheel), ProfileError);
  EXPECT_THROW(make_profile(data("small_rail.ban"), ProfileSide::kWheel), ProfileError);
}

// Good small files: orientation and unit conventions of each reader.
TEST(ProfileFileFormats, SmallGoodFiles) {
  // Text in metres with a cant directive: columns used as (u, v) directly.
  const ProfilePtr rail = read_profile_file(data("rail_metres.txt"), ProfileSide::kRail);
  EXPECT_DOUBLE_EQ(rail->lower(), -0.02);
  EXPECT_DOUBLE_EQ(rail->upper(), 0.02);
  EXPECT_NEAR(rail->evaluate(0.01).height, -0.0005, 1e-15);
  EXPECT_DOUBLE_EQ(rail->built_in_cant(), 0.05);
  // MiniProf: u = -X, v = -Y in mm; the points are those of v = -u^2/16 mm: the spline with
  // parabolic end curvature reproduces a parabola exactly.
  const ProfilePtr ban = read_profile_file(data("small_rail.ban"), ProfileSide::kRail);
  EXPECT_DOUBLE_EQ(ban->lower(), -0.004);
  EXPECT_NEAR(ban->evaluate(0.001).height, -0.0625e-3, 1e-15);
  EXPECT_NEAR(ban->evaluate(0.003).second_derivative, -1.0 / 8.0 * 1e3, 1e-9);
  EXPECT_EQ(ban->built_in_cant(), 0.0);
  ProfileFileOptions options;
  options.built_in_cant = 0.025;
  EXPECT_EQ(read_profile_file(data("small_rail.ban"), ProfileSide::kRail, options)->built_in_cant(),
            0.025);
  // Shipped text cone (mm, header line, side directive) equals the analytic cone.
  const ProfilePtr cone = make_profile(std::string(WRC_PROFILES_DIR) + "/conic_1in40_wheel.txt",
                                       ProfileSide::kWheel);
  EXPECT_NEAR(cone->evaluate(0.0123).height, -0.0123 / 40, 1e-12);
  EXPECT_NEAR(cone->evaluate(-0.0371).slope, -1.0 / 40, 1e-9);
}

}  // namespace
}  // namespace wrc
