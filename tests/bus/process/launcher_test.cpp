// SPDX-License-Identifier: Apache-2.0
// `wrc launch` with real processes: a killed service is restarted and the restart is logged;
// Ctrl-C stops every service (DRAINING, nothing left); a killed launcher takes its services along.
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>

#include <fstream>

#include "bus/transport/clock.hpp"
#include "bus_fixture.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus::test {
namespace {

class LauncherTest : public BusTest {
 protected:
  std::unique_ptr<ChildProcess> start_launcher() {
    const std::string profile = temp_path("profile.txt");
    std::ofstream(profile) << "# test profile\npingd wrc-pingd --instance L --heartbeat-period 0.1\n"
                              "missing wrc-nonexistentd\n";
    log_ = temp_path("launch.log");
    return std::make_unique<ChildProcess>(
        WRC_CLI_PATH,
        std::vector<std::string>{"launch", "--profile", profile, "--build-dir", WRC_TEST_BUILD_DIR,
                                 "--backoff-min", "0.05", "--grace", "2"},
        log_);
  }
  int live_pid() { return monitor_->find("pingd", "L", monotonic_seconds())->last.pid; }
  std::string log_;
};

// Kill -9 of the service: the launcher logs name, pid, signal and delay and starts a new one;
// SIGINT to the launcher: DRAINING from the service, launcher exits 0, no process left.
TEST_F(LauncherTest, RestartsKilledServiceAndStopsAllOnCtrlC) {
  auto launcher = start_launcher();
  ASSERT_TRUE(wait_ready("pingd", "L", 5.0)) << read_text(log_);
  const int first = live_pid();
  ASSERT_EQ(::kill(first, SIGKILL), 0);
  ASSERT_TRUE(wait_ready("pingd", "L", 5.0, first)) << "no restart:\n" << read_text(log_);
  const int second = live_pid();
  EXPECT_NE(second, first);
  const std::string text = read_text(log_);
  EXPECT_NE(text.find("launch: skipping missing: wrc-nonexistentd is not built"), std::string::npos) << text;
  EXPECT_NE(text.find("launch: pingd (pid " + std::to_string(first) + ") killed by signal 9"), std::string::npos)
      << text;
  EXPECT_NE(text.find("restart #1 in 0.05 s"), std::string::npos) << text;
  EXPECT_NE(text.find("launch: started pingd (pid " + std::to_string(second) + ")"), std::string::npos) << text;

  launcher->signal(SIGINT);
  EXPECT_TRUE(handle_until(
      [&] { return monitor_->find("pingd", "L", monotonic_seconds())->last.state == wrc::heartbeat_t::DRAINING; },
      3.0));
  int status = -1;
  ASSERT_TRUE(launcher->wait(5.0, &status)) << read_text(log_);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  EXPECT_TRUE(process_gone(first));
  EXPECT_TRUE(process_gone(second));
  EXPECT_NE(read_text(log_).find("launch: all services stopped"), std::string::npos);
}

// Even SIGKILL of the launcher leaves no service behind (PR_SET_PDEATHSIG in the children).
TEST_F(LauncherTest, KilledLauncherTakesServicesAlong) {
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);  // orphans come to this process, so we can see them end
  auto launcher = start_launcher();
  ASSERT_TRUE(wait_ready("pingd", "L", 5.0)) << read_text(log_);
  const int service = live_pid();
  launcher->signal(SIGKILL);
  ASSERT_TRUE(launcher->wait(2.0));
  const double deadline = monotonic_seconds() + 3.0;
  while (!process_gone(service) && monotonic_seconds() < deadline) {
    lcm_->handleTimeout(10);
  }
  EXPECT_TRUE(process_gone(service)) << "service pid " << service << " survived its launcher";
  ::waitpid(service, nullptr, WNOHANG);
}

}  // namespace
}  // namespace wrc::bus::test
