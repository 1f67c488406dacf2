// SPDX-License-Identifier: Apache-2.0
// Channel names: prefix rules, length limit, regex escaping.
#include <gtest/gtest.h>

#include "bus/transport/channels.hpp"

namespace {
using wrc::bus::ChannelNames;

// Without a prefix the base name is used as is; with one it is "<prefix>.<base>".
TEST(ChannelNames, AppliesPrefix) {
  EXPECT_EQ(ChannelNames().name("HEARTBEAT"), "HEARTBEAT");
  EXPECT_EQ(ChannelNames("SIM1").name("HEARTBEAT"), "SIM1.HEARTBEAT");
  EXPECT_EQ(ChannelNames("SIM1").name("CONTACT_QUERY", "onepoint"), "SIM1.CONTACT_QUERY.onepoint");
}

// Bad prefixes and over-long names are refused with the bad value in the message.
TEST(ChannelNames, RejectsBadPrefixAndLongNames) {
  try {
    ChannelNames bad("a.b");
    FAIL() << "prefix with '.' accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'a.b'"), std::string::npos);
  }
  EXPECT_THROW(ChannelNames(std::string(60, 'P')).name("HEARTBEAT"), std::invalid_argument);
}

// '.' must be escaped so that a subscription to CONTACT_QUERY.onepoint matches only itself.
TEST(ChannelNames, EscapesRegexCharacters) {
  EXPECT_EQ(wrc::bus::regex_escape("A.B"), "A\\.B");
  EXPECT_EQ(wrc::bus::regex_escape("X_Y-1"), "X_Y-1");
  EXPECT_EQ(wrc::bus::regex_escape("a+(b)"), "a\\+\\(b\\)");
}
}  // namespace
