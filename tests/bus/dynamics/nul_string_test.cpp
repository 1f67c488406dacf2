// SPDX-License-Identifier: Apache-2.0
// A signed run command whose strings hold a NUL byte (run_id, model) is refused where it is decoded
// (bus/transport/decode.hpp: it does not encode back to its bytes), so wrc-dynamicsd never holds
// a run id it cannot put in a status: it used to start the run, fail to encode the status and exit
// with status 1, losing any run in progress.
#include <sys/wait.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bus/transport/channels.hpp"
#include "bus_fixture.hpp"
#include "wrc/run_command_t.hpp"

namespace wrc::bus::test {
namespace {

// The encoding of command with the byte at marker (which must occur once in the fields) set to 0.
// The search starts after LCM's 8-byte type fingerprint, which may hold the marker's byte by chance
// (run_command_t's fingerprint of interface version 18 holds a '#').
std::vector<std::uint8_t> encoded_with_nul(const run_command_t& command, const std::string& marker) {
  constexpr std::ptrdiff_t kFingerprintSize = 8;
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(command.getEncodedSize()));
  command.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const auto at = std::search(bytes.begin() + kFingerprintSize, bytes.end(), marker.begin(), marker.end());
  EXPECT_NE(at, bytes.end()) << marker;
  if (at != bytes.end()) *at = 0;
  return bytes;
}

TEST_F(BusTest, DynamicsServiceOutlivesNulBytesInCommandStrings) {
  const std::string log = temp_path("dynamicsd.log");
  ChildProcess dynamicsd(std::string(WRC_TEST_BUILD_DIR) + "/services/dynamicsd/wrc-dynamicsd",
                         {"--instance", "nul", "--heartbeat-period", "0.5"}, log);
  ASSERT_TRUE(wait_ready("dynamicsd", "nul", 20.0)) << read_text(log);

  run_command_t command{};
  command.request_id = 1;
  command.command = run_command_t::START;
  command.run_id = "run#with-nul";
  command.model = "onepoint";
  publish_signed_bytes(names_.name(channel::kRunCommand), encoded_with_nul(command, "#"));
  command.request_id = 2;
  command.run_id = "run-2";
  command.model = "one#point";
  publish_signed_bytes(names_.name(channel::kRunCommand), encoded_with_nul(command, "#"));
  command.request_id = 3;
  command.command = run_command_t::STOP;
  command.run_id = "stop#";
  publish_signed_bytes(names_.name(channel::kRunCommand), encoded_with_nul(command, "#"));

  // Three heartbeat periods later the service is still there and READY, and it said why it
  // dropped the commands.
  handle_until([] { return false; }, 1.5);
  int status = 0;
  EXPECT_FALSE(dynamicsd.wait(0.0, &status)) << "wrc-dynamicsd ended, status " << status << "\n" << read_text(log);
  EXPECT_TRUE(wait_ready("dynamicsd", "nul", 2.0)) << read_text(log);
  EXPECT_NE(read_text(log).find("does not encode back to the bytes received"), std::string::npos) << read_text(log);
}

}  // namespace
}  // namespace wrc::bus::test
