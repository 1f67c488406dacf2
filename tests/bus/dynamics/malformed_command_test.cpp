// SPDX-License-Identifier: Apache-2.0
// A signed run command of a kind wrc-dynamicsd does not know (command neither START nor STOP) or
// with an in_process flag neither 0 nor 1 gets a FAILED run status that says so, naming the value,
// and the service serves on; the command's run id reaches the log escaped (a newline in it shows
// as \x0a and cannot forge a log line). A 60 kB string is dropped as malformed and counted.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus_fixture.hpp"
#include "bus/transport/clock.hpp"
#include "wrc/contact_select_t.hpp"
#include "wrc/heartbeat_t.hpp"
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

// A contact selection whose instance name is 60 kB (it used to stall wrc-dynamicsd's heartbeats
// for 1.9 s while a run went on) is dropped where it is decoded and counted as malformed: the
// heartbeats come on time and the log names the field, not its content.
TEST_F(BusTest, A60kBStringIsDroppedAsMalformedAndCounted) {
  const std::string log = temp_path("dynamicsd.log");
  const double period = 0.2;
  ChildProcess dynamicsd(std::string(WRC_TEST_BUILD_DIR) + "/services/dynamicsd/wrc-dynamicsd",
                         {"--instance", "long", "--heartbeat-period", std::to_string(period)}, log);
  ASSERT_TRUE(wait_ready("dynamicsd", "long", 20.0)) << read_text(log);
  std::vector<double> beats;
  std::int64_t malformed_before = -1, malformed_after = -1;
  GuardedSubscription<heartbeat_t> heartbeats(
      *lcm_, names_.name(channel::kHeartbeat), "test heartbeats", [&](const heartbeat_t& h, const ReceivedMessage&) {
        if (h.model != "dynamicsd" || h.instance != "long") return;
        beats.push_back(monotonic_seconds());
        (malformed_before < 0 ? malformed_before : malformed_after) = h.dropped_malformed;
      });
  ASSERT_TRUE(handle_until([&] { return malformed_before >= 0; }, 5.0));
  contact_select_t select{};
  select.seq = 1;
  select.model = "spline";
  select.instance = std::string(60000, 'i');
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(select.getEncodedSize()));
  select.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const double sent = monotonic_seconds();
  publish_signed_bytes(names_.name(channel::kContactSelect), bytes);
  ASSERT_TRUE(handle_until([&] { return malformed_after > malformed_before; }, 5.0)) << read_text(log);
  EXPECT_EQ(malformed_after - malformed_before, 1);
  handle_until([] { return false; }, 3 * period);
  double gap = 0;
  for (std::size_t i = 1; i < beats.size(); ++i)
    if (beats[i] > sent) gap = std::max(gap, beats[i] - beats[i - 1]);
  std::printf("[ measured ] largest heartbeat gap after the 60 kB selection: %.3f s (period %.1f s)\n", gap, period);
  EXPECT_LT(gap, 2 * period);
  const std::string text = read_text(log);
  EXPECT_EQ(text.find(std::string(200, 'i')), std::string::npos) << "the string reached the log";
}

}  // namespace
}  // namespace wrc::bus::test
