// SPDX-License-Identifier: Apache-2.0
// Tests of the simple analytic test profiles (cone, circle) and of the profile factory.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/identity/geometry_key.hpp"
#include "core/profile/builtin_profiles.hpp"
#include "core/profile/circle_rail.hpp"
#include "core/profile/conic.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

// Cone: F(s) = -slope s exactly, radius decreasing to the field side, flange-less domain.
TEST(ProfileConic, ClosedForm) {
  const ConicProfile p(0.025);
  EXPECT_DOUBLE_EQ(p.evaluate(0.01).height, -0.00025);
  EXPECT_DOUBLE_EQ(p.evaluate(-0.02).height, 0.0005);
  EXPECT_DOUBLE_EQ(p.evaluate(0.0).slope, -0.025);
  EXPECT_EQ(p.evaluate(0.03).second_derivative, 0.0);
  EXPECT_DOUBLE_EQ(p.lower(), -0.06);
  EXPECT_DOUBLE_EQ(p.upper(), 0.06);
  EXPECT_EQ(p.side(), ProfileSide::kWheel);
}

// Circle: v = sqrt(R^2-u^2) - R, v' = -u/sqrt, v'' = -R^2/(R^2-u^2)^1.5; top at the origin;
// domain min(36 mm, 0.9 R).
TEST(ProfileCircle, ClosedForm) {
  const double r = 0.3;
  const CircleRailProfile p(r);
  const double u = 0.02;
  const double root = std::sqrt(r * r - u * u);
  EXPECT_NEAR(p.evaluate(u).height, root - r, 1e-16);
  EXPECT_NEAR(p.evaluate(u).slope, -u / root, 1e-15);
  EXPECT_NEAR(p.evaluate(u).second_derivative, -r * r / (root * root * root), 1e-12);
  EXPECT_EQ(p.evaluate(0.0).height, 0.0);
  EXPECT_DOUBLE_EQ(p.upper(), 0.036);
  EXPECT_DOUBLE_EQ(CircleRailProfile(0.02).upper(), 0.018);
  EXPECT_THROW(CircleRailProfile(-1.0), std::invalid_argument);
}

// The factory builds every named profile on its own side.
TEST(ProfileFactory, Names) {
  EXPECT_EQ(make_profile("S1002", ProfileSide::kWheel)->name(), "S1002 (analytic)");
  EXPECT_EQ(make_profile("UIC60", ProfileSide::kRail)->name(), "UIC60 (EN 60E1 analytic)");
  EXPECT_EQ(make_profile("UIC60-MB", ProfileSide::kRail)->name(),
            "UIC60-MB (Manchester variant, analytic)");
  const ProfilePtr cone = make_profile("conic:0.05", ProfileSide::kWheel);
  EXPECT_DOUBLE_EQ(cone->evaluate(0.01).height, -0.0005);
  const ProfilePtr circle = make_profile("circle:0.3", ProfileSide::kRail);
  EXPECT_DOUBLE_EQ(circle->upper(), 0.036);
  EXPECT_EQ(circle->side(), ProfileSide::kRail);
}

// Wrong side and malformed parameters are ProfileErrors that name the spec.
TEST(ProfileFactory, Errors) {
  const auto expect_error = [](const std::string& spec, ProfileSide side, const std::string& what) {
    try {
      make_profile(spec, side);
      ADD_FAILURE() << spec << " did not throw";
    } catch (const ProfileError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_EQ(e.source(), spec);
    }
  };
  expect_error("S1002", ProfileSide::kRail, "is a wheel profile, asked for as a rail");
  expect_error("UIC60", ProfileSide::kWheel, "is a rail profile, asked for as a wheel");
  expect_error("UIC60-MB", ProfileSide::kWheel, "rail profile");
  expect_error("conic:0.05", ProfileSide::kRail, "wheel profile");
  expect_error("circle:0.3", ProfileSide::kWheel, "rail profile");
  expect_error("conic:abc", ProfileSide::kWheel, "not a finite number");
  expect_error("conic:", ProfileSide::kWheel, "not a finite number");
  expect_error("conic:0.05x", ProfileSide::kWheel, "not a finite number");
  expect_error("circle:nan", ProfileSide::kRail, "not a finite number");
  expect_error("circle:-0.3", ProfileSide::kRail, "positive");
}

// Every name of the one list of built-ins builds a profile of its side, refused on the other side,
// and the geometry key names it instead of reading a file; the parameterised ones print their
// prefix in their names.
TEST(ProfileFactory, EveryBuiltinNameIsBuiltAndKeyedByName) {
  for (const BuiltinProfile& b : kBuiltinProfiles) {
    const ProfilePtr p = make_profile(b.name, b.side);
    ASSERT_TRUE(p) << b.name;
    EXPECT_EQ(p->side(), b.side) << b.name;
    EXPECT_EQ(find_builtin_profile(b.name), &b);
    const ProfileSide other = b.side == ProfileSide::kWheel ? ProfileSide::kRail : ProfileSide::kWheel;
    EXPECT_THROW(make_profile(b.name, other), ProfileError) << b.name;
    EXPECT_NO_THROW(profile_content_hash(b.name)) << b.name;  // a file of that name would not be there
  }
  EXPECT_EQ(find_builtin_profile("s1002"), nullptr);  // case-sensitive
  EXPECT_EQ(find_builtin_profile("UIC60-mb"), nullptr);
  EXPECT_EQ(make_profile(std::string(kConicPrefix) + "0.05", ProfileSide::kWheel)->name().rfind(kConicPrefix, 0), 0u);
  EXPECT_EQ(make_profile(std::string(kCirclePrefix) + "0.3", ProfileSide::kRail)->name().rfind(kCirclePrefix, 0), 0u);
}

}  // namespace
}  // namespace wrc
