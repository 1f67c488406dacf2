// SPDX-License-Identifier: Apache-2.0
// Two wrc-dynamicsd of one name on one bus (two launchers, say): the later one goes DUPLICATE and
// stays passive, so a run is executed and summarised by one process, not by both (both used to run every
// run and publish two summaries).
#include <sys/wait.h>

#include <cstdint>
#include <set>
#include <string>

#include "bus/service/service_loop.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus_fixture.hpp"
#include "wrc/run_summary_t.hpp"

namespace wrc::bus::test {
namespace {

TEST_F(BusTest, ADuplicateDynamicsServiceRunsNothing) {
  const std::string dynamicsd = std::string(WRC_TEST_BUILD_DIR) + "/services/dynamicsd/wrc-dynamicsd";
  ChildProcess first(dynamicsd, {"--heartbeat-period", "0.2"}, temp_path("first.log"));
  ASSERT_TRUE(wait_ready("dynamicsd", "0", 20.0)) << read_text(temp_path("first.log"));
  ChildProcess second(dynamicsd, {"--heartbeat-period", "0.2"}, temp_path("second.log"));
  ASSERT_TRUE(handle_until(
      [&] {
        for (const ServiceStatus& s : monitor_->services(monotonic_seconds()))
          if (s.last.pid == second.pid() && s.last.state == heartbeat_t::DUPLICATE) return true;
        return false;
      },
      20.0))
      << read_text(temp_path("second.log"));

  std::set<std::uint64_t> summarisers;  // sender nonces of the summaries (a summary is repeated)
  GuardedSubscription<run_summary_t> sub(*lcm_, names_.name(channel::kRunSummary), "test summaries",
                                         [&](const run_summary_t& s, const ReceivedMessage& info) {
                                           if (s.run_id == "dup") summarisers.insert(info.origin.nonce);
                                         });
  const std::string log = temp_path("run.log");
  ChildProcess cli(WRC_CLI_PATH,
                   {"run", "--model", "onepoint", "--in-process", "--t-end", "0.05", "--summary",
                    temp_path("dup.json"), "--run-id", "dup", "--build-dir", WRC_TEST_BUILD_DIR},
                   log);
  int status = -1;
  ASSERT_TRUE(handle_until([&] { return cli.wait(0.0, &status); }, 120.0)) << read_text(log);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
  handle_until([] { return false; }, 1.0);  // a second summary would come within this
  EXPECT_EQ(summarisers.size(), 1u) << read_text(temp_path("second.log"));
}

}  // namespace
}  // namespace wrc::bus::test
