// SPDX-License-Identifier: Apache-2.0
// Common service options: parsed, passed through, or refused with a message naming the value.
#include <gtest/gtest.h>

#include "bus/service/service_options.hpp"

namespace {
using wrc::bus::ServiceOptions;

ServiceOptions parse(std::vector<const char*> args) {
  args.insert(args.begin(), "prog");
  return ServiceOptions::parse(static_cast<int>(args.size()), args.data());
}

// Own options are consumed (both `--x v` and `--x=v`), others kept in order.
TEST(ServiceOptions, ParsesAndPassesThrough) {
  auto o = parse({"--model", "onepoint", "--channel-prefix", "SIM1", "--instance=b", "--lcm-url",
                  "memq://", "--heartbeat-period", "0.2", "-v"});
  EXPECT_EQ(o.channel_prefix, "SIM1");
  EXPECT_EQ(o.instance, "b");
  EXPECT_EQ(o.lcm_url, "memq://");
  EXPECT_DOUBLE_EQ(o.heartbeat_period, 0.2);
  EXPECT_EQ(o.rest, (std::vector<std::string>{"--model", "onepoint", "-v"}));
  EXPECT_FALSE(o.help);
  EXPECT_TRUE(parse({"--help"}).help);
}

// Given twice, the last one wins (`wrc launch --lcm-url U` appends to the profile's line); an
// unknown option's `=value` form passes through verbatim; --help lists every option.
TEST(ServiceOptions, LastWinsAndHelpFromTheTable) {
  auto o = parse({"--instance", "a", "--model=spline", "--lcm-url", "udpm://", "--instance", "b", "--lcm-url=memq://"});
  EXPECT_EQ(o.instance, "b");
  EXPECT_EQ(o.lcm_url, "memq://");
  EXPECT_EQ(o.rest, (std::vector<std::string>{"--model=spline"}));
  const std::string help = ServiceOptions::help_text();
  for (const char* name : {"--lcm-url", "--channel-prefix", "--instance", "--heartbeat-period"})
    EXPECT_NE(help.find(name), std::string::npos) << name;
}

// Expects parse(args) to throw std::invalid_argument whose message contains `expected`.
void expect_refused(std::vector<const char*> args, const std::string& expected) {
  try {
    parse(std::move(args));
    ADD_FAILURE() << "accepted, expected '" << expected << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// Bad values are refused with the option, the value and the rule named. Options that are not the
// services' own are not refused here: they pass through to the service (ContactdOptions names an
// unknown one, contactd_options_test.cpp).
TEST(ServiceOptions, RefusesBadValues) {
  expect_refused({"--heartbeat-period", "-1"}, "--heartbeat-period: '-1' is not a number in [0.01, 10] s");
  expect_refused({"--heartbeat-period=11"}, "--heartbeat-period: '11' is not a number in [0.01, 10] s");
  expect_refused({"--heartbeat-period", "0.005"}, "--heartbeat-period: '0.005' is not a number in [0.01, 10] s");
  expect_refused({"--heartbeat-period", "fast"}, "--heartbeat-period: 'fast' is not a number");
  expect_refused({"--instance", "a b"}, "--instance: 'a b' must be 1-24 letters, digits, '_' or '-'");
  expect_refused({"--instance", "abcdefghijklmnopqrstuvwxy"}, "--instance: 'abcdefghijklmnopqrstuvwxy' must be 1-24");
  expect_refused({"--lcm-url"}, "option --lcm-url needs a value");
  // A forgotten value: the next option is not taken for it, and both are named.
  expect_refused({"--instance", "--heartbeat-period", "0.5"},
                 "option --instance needs a value, but the next argument is the option '--heartbeat-period'");
}
}  // namespace
