// SPDX-License-Identifier: Apache-2.0
// The URL rule of bus/transport/lcm_url.hpp: a udpm URL without recv_buf_size gets one no larger than the
// kernel allows; anything else is kept as the user wrote it.
#include "bus/transport/lcm_url.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace wrc::bus {
namespace {

long rmem_max() {
  std::ifstream in("/proc/sys/net/core/rmem_max");
  long v = 0;
  in >> v;
  return v;
}

std::string expected_buffer() { return std::to_string(std::min(kWantedReceiveBufferBytes, rmem_max())); }

class LcmUrlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const char* env = std::getenv("LCM_DEFAULT_URL")) saved_ = env, had_ = true;
    ::unsetenv("LCM_DEFAULT_URL");
    if (rmem_max() <= 0) GTEST_SKIP() << "net.core.rmem_max cannot be read here";
  }
  void TearDown() override {
    if (had_) ::setenv("LCM_DEFAULT_URL", saved_.c_str(), 1);
  }
  std::string saved_;
  bool had_ = false;
};

TEST_F(LcmUrlTest, DefaultBusGetsTheCappedReceiveBuffer) {
  EXPECT_EQ(effective_lcm_url(""), "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=" + expected_buffer());
}

TEST_F(LcmUrlTest, EnvironmentUrlIsUsedAndCompleted) {
  ::setenv("LCM_DEFAULT_URL", "udpm://239.255.76.67:7700", 1);
  EXPECT_EQ(effective_lcm_url(""), "udpm://239.255.76.67:7700?recv_buf_size=" + expected_buffer());
  EXPECT_EQ(effective_lcm_url("udpm://239.255.76.67:7701?ttl=1"),
            "udpm://239.255.76.67:7701?ttl=1&recv_buf_size=" + expected_buffer())
      << "an explicit URL wins over the environment";
}

TEST_F(LcmUrlTest, UrlsThatChooseTheirBufferOrAnotherProviderAreKept) {
  EXPECT_EQ(effective_lcm_url("udpm://239.255.76.67:7667?recv_buf_size=1000"), "udpm://239.255.76.67:7667?recv_buf_size=1000");
  EXPECT_EQ(effective_lcm_url("memq://"), "memq://");
  EXPECT_EQ(effective_lcm_url("file:///tmp/x.lcmlog?mode=w"), "file:///tmp/x.lcmlog?mode=w");
}

}  // namespace
}  // namespace wrc::bus
