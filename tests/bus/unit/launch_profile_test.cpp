// SPDX-License-Identifier: Apache-2.0
// Launch profiles: parsing, comments, selection, and errors naming file, line and service.
#include <gtest/gtest.h>

#include "bus/process/launch_profile.hpp"

namespace {
using namespace wrc::bus;

// Lines, comments and arguments are read; selection keeps the requested order.
TEST(LaunchProfile, ParsesAndSelects) {
  const auto profile = parse_launch_profile(
      "# comment\n\nping wrc-pingd --instance a  # trailing comment\ngeo wrc-geometryd\n", "p.txt");
  ASSERT_EQ(profile.size(), 2u);
  EXPECT_EQ(profile[0].name, "ping");
  EXPECT_EQ(profile[0].executable, "wrc-pingd");
  EXPECT_EQ(profile[0].args, (std::vector<std::string>{"--instance", "a"}));
  EXPECT_EQ(profile[0].line, 3);
  EXPECT_EQ(select_services(profile, {}).size(), 2u);
  const auto picked = select_services(profile, {"geo", "ping"});
  EXPECT_EQ(picked[0].name, "geo");
  EXPECT_EQ(picked[1].name, "ping");
}

// Missing executables, duplicates and unknown names are refused with a precise message.
TEST(LaunchProfile, RefusesBadProfiles) {
  try {
    parse_launch_profile("a x\nb\n", "p.txt");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "p.txt:2: service 'b' has no executable");
  }
  EXPECT_THROW(parse_launch_profile("a x\na y\n", "p.txt"), std::invalid_argument);
  const auto profile = parse_launch_profile("a x\n", "p.txt");
  try {
    select_services(profile, {"zz"});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown service 'zz' (the profile has: a)");
  }
  EXPECT_THROW(read_launch_profile("/nonexistent/profile.txt"), std::runtime_error);
}
}  // namespace
