// SPDX-License-Identifier: Apache-2.0
// The URL rule of bus/transport/lcm_url.hpp: a udpm URL without recv_buf_size gets one no larger than the
// kernel allows; anything else is kept as the user wrote it.
#include "bus/transport/lcm_url.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>
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

// Lanes: the same group and options, the port moved by the lane; nothing for providers without
// multicast ports; bad lanes and ports named.
TEST(LaneUrl, IsTheBusOnItsPortPlusTheLane) {
  EXPECT_EQ(lane_lcm_url("udpm://239.255.76.67:7667?ttl=1&recv_buf_size=4194304", 4),
            "udpm://239.255.76.67:7671?ttl=1&recv_buf_size=4194304");
  EXPECT_EQ(lane_lcm_url("udpm://239.1.2.3:9000", 1), "udpm://239.1.2.3:9001");
  EXPECT_EQ(lane_lcm_url("udpm://239.1.2.3?ttl=0", 8), "udpm://239.1.2.3:7675?ttl=0");  // LCM's default port
  EXPECT_EQ(lane_lcm_url("memq://", 1), "");
  EXPECT_EQ(lane_lcm_url("file:///tmp/x.log?mode=r", 1), "");
}

TEST(LaneUrl, RefusesLanesAndPortsOutOfRangeNamingThem) {
  for (int lane : {0, -1, kMaxLanes + 1}) {
    try {
      lane_lcm_url("udpm://239.255.76.67:7667", lane);
      ADD_FAILURE() << "lane " << lane << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("lane " + std::to_string(lane)), std::string::npos) << e.what();
    }
  }
  for (const char* url : {"udpm://239.255.76.67:x?ttl=0", "udpm://239.255.76.67:65530", "udpm://239.255.76.67:0",
                          "udpm://239.255.76.67:"}) {
    EXPECT_THROW(lane_lcm_url(url, 1), std::invalid_argument) << url;
  }
}

}  // namespace
}  // namespace wrc::bus
