// Common service options: parsed, passed through, or refused with a message naming the value.
#include <gtest/gtest.h>

#include "bus/service_options.hpp"

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

// Bad values are refused and named.
TEST(ServiceOptions, RefusesBadValues) {
  try {
    parse({"--heartbeat-period", "-1"});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'-1'"), std::string::npos);
  }
  EXPECT_THROW(parse({"--instance", "a b"}), std::invalid_argument);
  EXPECT_THROW(parse({"--lcm-url"}), std::invalid_argument);
}
}  // namespace
