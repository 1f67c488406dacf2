// SPDX-License-Identifier: Apache-2.0
// `wrc spy`'s real launch path (not --print-command): it execs `lcm-spy` found on PATH with the
// project's types jar on CLASSPATH (before any CLASSPATH the user had), the JVM option that lets
// Debian's lcm-spy script start on Java 17, and --lcm-url passed through. A stand-in lcm-spy first
// on PATH records what it was started with (the real one needs a display).
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "bus_fixture.hpp"

namespace wrc::bus::test {
namespace {

TEST_F(BusTest, SpyExecsLcmSpyWithTheTypesOnItsClassPath) {
  const std::string bin = temp_path("bin");
  std::filesystem::create_directories(bin);
  const std::string record = temp_path("spy-record.txt");
  {
    std::ofstream script(bin + "/lcm-spy");
    script << "#!/bin/sh\n"
           << "{ echo \"CLASSPATH=$CLASSPATH\"; echo \"JDK_JAVA_OPTIONS=$JDK_JAVA_OPTIONS\"; echo \"ARGS=$*\"; } > '"
           << record << "'\n";
  }
  ::chmod((bin + "/lcm-spy").c_str(), 0755);
  const std::string jar = std::string(WRC_TEST_BUILD_DIR) + "/lcmtypes/wrc_lcmtypes_java.jar";
  int status = -1;
  const std::string out = run_command("PATH='" + bin + "':\"$PATH\" CLASSPATH=/user/extra.jar " +
                                          std::string(WRC_CLI_PATH) + " spy --lcm-url 'udpm://239.255.76.67:7667?ttl=0' 2>&1",
                                      &status);
  ASSERT_EQ(status, 0) << out;
  const std::string text = read_text(record);
  EXPECT_NE(text.find("CLASSPATH=" + jar + ":/user/extra.jar\n"), std::string::npos) << text;
  EXPECT_NE(text.find("JDK_JAVA_OPTIONS=-XX:+IgnoreUnrecognizedVMOptions\n"), std::string::npos) << text;
  EXPECT_NE(text.find("ARGS=--lcm-url=udpm://239.255.76.67:7667?ttl=0\n"), std::string::npos) << text;

  // Without lcm-spy anywhere on PATH the command says what to install and fails.
  const std::string missing =
      run_command("PATH=/nonexistent " + std::string(WRC_CLI_PATH) + " spy 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(missing.find("cannot run lcm-spy"), std::string::npos) << missing;
}

}  // namespace
}  // namespace wrc::bus::test
