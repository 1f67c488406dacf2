// SPDX-License-Identifier: Apache-2.0
// The launcher's hang check (bus/process/process_supervisor.hpp) on real child processes, with
// heartbeats fed in by hand: silence kills a child fast only when its process state confirms it
// is stopped (SIGSTOP), otherwise only after a silence no lossy network produces; heartbeats
// count only from the child's own identity (the nonce of its first heartbeat); and time the
// supervisor itself was away is not the children's silence. Intervals: periods of 0.05 s, so
// hang_periods = 2 is 0.1 s and unconfirmed_hang_periods = 20 is 1 s; the checks sit at least
// 0.3 s away from each threshold, far more than a poll interval (5 ms) or a loaded machine's
// scheduling delay.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <sstream>
#include <thread>

#include "bus/process/process_supervisor.hpp"
#include "bus/transport/clock.hpp"

namespace {
using namespace wrc::bus;

constexpr double kPeriod = 0.05;  // [s] the children's declared heartbeat period

class SupervisorLiveness : public ::testing::Test {
 protected:
  SupervisorLiveness() {
    policy_.hang_periods = 2.0;
    policy_.unconfirmed_hang_periods = 20.0;
    policy_.backoff_min = 30.0;  // a killed child stays down for the rest of the test
    policy_.backoff_max = 30.0;
  }
  void start() {
    supervisor_ = std::make_unique<ProcessSupervisor>(
        std::vector<ChildSpec>{{"sleeper", "/bin/sh", {"-c", "exec sleep 30"}}}, policy_, log_);
    supervisor_->start_all();
    pid_ = supervisor_->children()[0].pid;
    ASSERT_GT(pid_, 0);
  }
  void TearDown() override {
    if (supervisor_) {
      ::kill(pid_, SIGCONT);
      supervisor_->stop_all();
    }
  }
  // Polls every 5 ms for seconds [s], feeding a heartbeat from nonce every poll when nonce != 0.
  void poll_for(double seconds, std::uint64_t nonce = 0, double period = kPeriod) {
    const double end = monotonic_seconds() + seconds;
    while (monotonic_seconds() < end) {
      if (nonce != 0) supervisor_->heartbeat_seen(pid_, nonce, period, monotonic_seconds());
      supervisor_->poll();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  int hangs() const { return supervisor_->children()[0].hangs; }

  SupervisorPolicy policy_;
  std::ostringstream log_;
  std::unique_ptr<ProcessSupervisor> supervisor_;
  pid_t pid_ = -1;
};

TEST(ProcessState, StoppedIsReadFromProc) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::pause();
    ::_exit(0);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(process_stopped(child));
  ::kill(child, SIGSTOP);
  bool stopped = false;
  for (int i = 0; i < 200 && !(stopped = process_stopped(child)); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(stopped);
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  EXPECT_FALSE(process_stopped(child));  // gone: nothing to read
}

// Heartbeats lost on the way (the process runs, sleeping): no kill after 2 periods, nor after
// 10; killed once 20 periods have passed in silence, with the reason in the log.
TEST_F(SupervisorLiveness, SilenceOfARunningChildKillsOnlyAfterTheLongLimit) {
  start();
  poll_for(0.1, 7);  // heartbeats arrive
  poll_for(0.6);     // 12 periods of silence
  EXPECT_EQ(hangs(), 0) << log_.str();
  poll_for(0.8);     // 28 periods
  EXPECT_EQ(hangs(), 1) << log_.str();
  EXPECT_NE(log_.str().find("is silent, not stopped: killing it"), std::string::npos) << log_.str();
}

// A stopped child (SIGSTOP) is killed after hang_periods, as before.
TEST_F(SupervisorLiveness, AStoppedChildIsKilledAfterTwoPeriods) {
  start();
  poll_for(0.1, 7);
  ASSERT_EQ(::kill(pid_, SIGSTOP), 0);
  poll_for(0.4);  // 8 periods: past 2, far below 20
  EXPECT_EQ(hangs(), 1) << log_.str();
  EXPECT_NE(log_.str().find("and is stopped: killing it"), std::string::npos) << log_.str();
}

// Heartbeats that name the child's pid under another nonce neither keep a stopped child alive nor
// change its period: the first heartbeat (period 0.25 s: hang after 0.5 s) fixes both; a
// spoofer's stream with period 0.01 s does not shorten that to 0.02 s.
TEST_F(SupervisorLiveness, OnlyTheChildsOwnHeartbeatsCount) {
  start();
  supervisor_->heartbeat_seen(pid_, 7, 0.25, monotonic_seconds());
  ASSERT_EQ(::kill(pid_, SIGSTOP), 0);
  poll_for(0.2, 99, 0.01);  // spoofed, with a short period: not hung at 0.2 s
  EXPECT_EQ(hangs(), 0) << log_.str();
  poll_for(0.6, 99, 0.01);  // 0.8 s after its own last heartbeat: hung although "heartbeats" came
  EXPECT_EQ(hangs(), 1) << log_.str();
  EXPECT_DOUBLE_EQ(supervisor_->children()[0].heartbeat_period, 0.25);
}

// The supervisor away for 1.5 s (30 periods; its loop behind a flood of messages, or
// descheduled): no kill, because its own delay is not the child's silence.
TEST_F(SupervisorLiveness, TheSupervisorsOwnDelayIsNotSilence) {
  start();
  poll_for(0.1, 7);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  poll_for(0.3);  // 6 periods after the supervisor came back
  EXPECT_EQ(hangs(), 0) << log_.str();
}

}  // namespace
