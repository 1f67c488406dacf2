// SPDX-License-Identifier: Apache-2.0
// Process supervisor with real short-lived processes: restart with growing back-off and a log
// line per death; stop_all ends a child that ignores SIGTERM with SIGKILL.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>

#include <unistd.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <thread>

#include "bus/process/process_supervisor.hpp"
#include "bus/transport/clock.hpp"

namespace {
using namespace wrc::bus;

// A child that exits at once is restarted; the delays double (0.02, 0.04, ...); each death is
// logged with name, pid and exit status.
TEST(ProcessSupervisor, RestartsWithBackoffAndLogs) {
  std::ostringstream log;
  SupervisorPolicy policy;
  policy.backoff_min = 0.02;
  policy.backoff_max = 0.08;
  ProcessSupervisor supervisor({{"quitter", "/bin/sh", {"-c", "exit 3"}}}, policy, log);
  supervisor.start_all();
  const double deadline = monotonic_seconds() + 5.0;
  while (supervisor.children()[0].restarts < 4 && monotonic_seconds() < deadline) {
    supervisor.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  supervisor.stop_all();
  ASSERT_GE(supervisor.children()[0].restarts, 4) << log.str();
  const std::string text = log.str();
  EXPECT_NE(text.find("quitter (pid "), std::string::npos);
  EXPECT_NE(text.find(") exited with status 3 after"), std::string::npos) << text;
  EXPECT_NE(text.find("restart #1 in 0.02 s"), std::string::npos) << text;
  EXPECT_NE(text.find("restart #2 in 0.04 s"), std::string::npos) << text;
  EXPECT_NE(text.find("restart #4 in 0.08 s"), std::string::npos) << text;
}

// A child that ignores SIGTERM is killed after the grace period; nothing is left running.
TEST(ProcessSupervisor, StopKillsStubbornChild) {
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);
  std::ostringstream log;
  SupervisorPolicy policy;
  policy.grace = 0.2;
  // The shell says it has installed its trap by creating a marker file, which the test polls for.
  const std::string marker = ::testing::TempDir() + "stubborn_" + std::to_string(::getpid());
  std::remove(marker.c_str());
  ProcessSupervisor supervisor(
      {{"stubborn", "/bin/sh", {"-c", "trap '' TERM; : > '" + marker + "'; while :; do sleep 0.05; done"}}}, policy,
      log);
  supervisor.start_all();
  const pid_t pid = supervisor.children()[0].pid;
  ASSERT_GT(pid, 0);
  const double ready_by = monotonic_seconds() + 10.0;
  while (::access(marker.c_str(), F_OK) != 0 && monotonic_seconds() < ready_by)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(::access(marker.c_str(), F_OK), 0) << "the child never installed its trap";
  std::remove(marker.c_str());
  const double start = monotonic_seconds();
  supervisor.stop_all();
  EXPECT_GE(monotonic_seconds() - start, 0.19);
  EXPECT_NE(log.str().find("did not stop within 0.2 s, sending SIGKILL"), std::string::npos) << log.str();
  EXPECT_NE(log.str().find("killed by signal 9"), std::string::npos) << log.str();
  EXPECT_EQ(::kill(pid, 0), -1);  // the child is gone and reaped
  // its process group (the shell's sleep) is gone too; the orphaned sleep is re-parented to this
  // process (a subreaper), so reap it here instead of depending on init
  const double deadline = monotonic_seconds() + 2.0;
  while (::kill(-pid, 0) == 0 && monotonic_seconds() < deadline) {
    ::waitpid(-pid, nullptr, WNOHANG);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(::kill(-pid, 0), -1);
}

// Exit descriptions name the status or the signal.
TEST(ProcessSupervisor, DescribesExit) {
  EXPECT_EQ(describe_exit(3 << 8), "exited with status 3");
  EXPECT_EQ(describe_exit(SIGKILL).rfind("killed by signal 9 (", 0), 0u);
}
}  // namespace
