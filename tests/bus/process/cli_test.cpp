// SPDX-License-Identifier: Apache-2.0
// `wrc status` and `wrc spy` as the user runs them, and the types jar lcm-spy depends on.
#include <cstdio>
#include <filesystem>
#include <set>

#include "bus_fixture.hpp"

namespace wrc::bus::test {
namespace {

const std::string kJar = std::string(WRC_TEST_BUILD_DIR) + "/lcmtypes/wrc_lcmtypes_java.jar";

// `wrc status` lists a running service with its model, instance, pid, state and channel.
TEST_F(BusTest, StatusListsLiveService) {
  auto pingd = start_pingd("s", 0.1);
  ASSERT_TRUE(wait_ready("pingd", "s", 5.0));
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " status --duration 0.5 --format csv", &status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.find("model,instance,pid,state"), std::string::npos) << out;
  EXPECT_NE(out.find("pingd,s," + std::to_string(pingd->pid()) + ",READY,1,"), std::string::npos) << out;
  EXPECT_NE(out.find(",PING,\"serving pings, "), std::string::npos) << out;
}

// `wrc spy` runs lcm-spy with the types jar on CLASSPATH and the Java 17 workaround.
TEST(Spy, PrintsTheCommandItRuns) {
  int status = -1;
  const std::string out =
      run_command(std::string(WRC_CLI_PATH) + " spy --print-command --lcm-url udpm://239.255.76.67:7667?ttl=0", &status);
  EXPECT_EQ(status, 0);
  EXPECT_EQ(out, "CLASSPATH=" + kJar +
                     " JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions lcm-spy "
                     "--lcm-url=udpm://239.255.76.67:7667?ttl=0\n");
  const std::string bad = run_command(std::string(WRC_CLI_PATH) + " spy --print-command --jar /nonexistent.jar 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(bad.find("'/nonexistent.jar' does not exist"), std::string::npos) << bad;
}

// The jar holds a class for every .lcm type, so lcm-spy can decode every message.
TEST(Spy, JarHoldsEveryType) {
  int status = -1;
  const std::string listing = run_command("jar tf " + kJar, &status);
  ASSERT_EQ(status, 0) << "cannot list " << kJar;
  int types = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(WRC_SOURCE_DIR) + "/lcmtypes")) {
    if (entry.path().extension() != ".lcm") continue;
    ++types;
    const std::string cls = "wrc/" + entry.path().stem().string() + ".class";
    EXPECT_NE(listing.find(cls), std::string::npos) << cls << " missing from the jar";
  }
  EXPECT_GE(types, 20);
}

}  // namespace
}  // namespace wrc::bus::test
