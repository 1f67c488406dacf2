// SPDX-License-Identifier: Apache-2.0
// A signed run command of a kind wrc-dynamicsd does not know (command neither START nor STOP) or
// with an in_process flag neither 0 nor 1 gets a FAILED run status that says so, naming the value,
// and the service serves on; the command's run id reaches the log escaped (a newline in it shows
// as \x0a and cannot forge a log line).
#include <string>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus_fixture.hpp"
#include "wrc/run_command_t.hpp"
#include "wrc/run_status_t.hpp"

namespace wrc::bus::test {
namespace {

TEST_F(BusTest, AnUnknownCommandOrInProcessValueGetsAStatusThatSaysSo) {
  const std::string log = temp_path("dynamicsd.log");
  ChildProcess dynamicsd(std::string(WRC_TEST_BUILD_DIR) + "/services/dynamicsd/wrc-dynamicsd",
                         {"--instance", "odd", "--heartbeat-period", "0.5"}, log);
  ASSERT_TRUE(wait_ready("dynamicsd", "odd", 20.0)) << read_text(log);
  run_status_t last{};
  GuardedSubscription<run_status_t> statuses(*lcm_, names_.name(channel::kRunStatus), "test run status",
                                             [&](const run_status_t& s, const ReceivedMessage&) { last = s; });

  run_command_t command{};
  command.request_id = 1;
  command.command = 7;
  command.run_id = "odd-command";
  command.model = "onepoint";
  publish_signed(*lcm_, names_.name(channel::kRunCommand), command);
  ASSERT_TRUE(handle_until([&] { return last.request_id == 1; }, 10.0)) << read_text(log);
  EXPECT_EQ(last.state, run_status_t::FAILED);
  EXPECT_EQ(last.message, "command = 7 is neither START (0) nor STOP (1); ignored");

  command.request_id = 2;
  command.command = run_command_t::START;
  command.in_process = 5;
  command.run_id = "odd\nwrc-dynamicsd: forged line";
  publish_signed(*lcm_, names_.name(channel::kRunCommand), command);
  ASSERT_TRUE(handle_until([&] { return last.request_id == 2; }, 10.0)) << read_text(log);
  EXPECT_EQ(last.state, run_status_t::FAILED);
  EXPECT_NE(last.message.find("in_process = 5 is neither 0 nor 1"), std::string::npos) << last.message;
  EXPECT_TRUE(wait_ready("dynamicsd", "odd", 5.0)) << read_text(log);
  const std::string text = read_text(log);
  EXPECT_NE(text.find("run odd\\x0awrc-dynamicsd: forged line failed to start"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nwrc-dynamicsd: forged line"), std::string::npos) << text;
}

}  // namespace
}  // namespace wrc::bus::test
