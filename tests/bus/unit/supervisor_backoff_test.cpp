// SPDX-License-Identifier: Apache-2.0
// The process supervisor's restart back-off, decided (its log) and measured from the children
// themselves: each child appends the monotonic time at which it started to a file, and the intervals
// between those starts are checked against process_supervisor.hpp's policy (backoff_min, doubling
// per short-lived run up to backoff_max; backoff_min again after a run of stable_after or more).
//
// The child is this test binary itself: a static initialiser runs before gtest's main when
// WRC_TEST_STAMP_FILE is set in the environment, writes CLOCK_MONOTONIC there (the clock of
// bus::monotonic_seconds, which the supervisor's deadlines use), sleeps WRC_TEST_STAMP_SLEEP
// seconds if given, and exits 0.
//
// What is asserted. The delays the supervisor decided, from its log ("restart #k in D s"), equal
// the policy's sequence exactly. The measured intervals are bounded below, strictly: the
// supervisor schedules a restart `delay` after it saw the death, which is after the dead child
// wrote its stamp (and after its sleep), and the next child writes its stamp after being started,
// so an interval is never shorter than delay (+ sleep); a restart earlier than decided fails
// that. What comes on top (the child's exit, the supervisor's 5 ms poll, fork and exec) depends on
// the machine's load and is printed, not asserted.
#include <gtest/gtest.h>

#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bus/process/process_supervisor.hpp"
#include "bus/transport/clock.hpp"

namespace {

// The child's part: stamp, sleep, exit, before anything of gtest runs.
const bool kIsStampChild = [] {
  const char* file = std::getenv("WRC_TEST_STAMP_FILE");
  if (file == nullptr) return false;
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);
  if (FILE* out = std::fopen(file, "a")) {
    std::fprintf(out, "%lld.%09ld\n", static_cast<long long>(now.tv_sec), now.tv_nsec);
    std::fclose(out);
  }
  if (const char* sleep = std::getenv("WRC_TEST_STAMP_SLEEP"))
    std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(sleep)));
  std::_Exit(0);
}();

using namespace wrc::bus;

// The delays "restart #k in D s" of the supervisor's log, in order [s].
std::vector<double> logged_delays(const std::string& log) {
  std::vector<double> delays;
  const std::string tag = "; restart #";
  for (std::size_t at = log.find(tag); at != std::string::npos; at = log.find(tag, at + 1)) {
    const std::size_t in = log.find(" in ", at);
    if (in == std::string::npos) break;
    delays.push_back(std::strtod(log.c_str() + in + 4, nullptr));
  }
  return delays;
}

std::string self_path() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return {};
  return std::string(buf, static_cast<size_t>(n));
}

std::vector<double> read_stamps(const std::string& path) {
  std::vector<double> stamps;
  std::ifstream in(path);
  double t;
  while (in >> t) stamps.push_back(t);
  return stamps;
}

// Supervises this binary as a stamping child until it has started `starts` times (or 30 s pass);
// returns the start times the children wrote.
std::vector<double> supervised_starts(const SupervisorPolicy& policy, int starts, double child_sleep,
                                      std::string& log_text) {
  const std::string file = ::testing::TempDir() + "supervisor_stamps_" + std::to_string(::getpid()) + ".txt";
  std::remove(file.c_str());
  ::setenv("WRC_TEST_STAMP_FILE", file.c_str(), 1);
  if (child_sleep > 0) ::setenv("WRC_TEST_STAMP_SLEEP", std::to_string(child_sleep).c_str(), 1);
  std::ostringstream log;
  {
    // "--gtest_filter=-*": should the initialiser not act, the child runs no test at all.
    ProcessSupervisor supervisor({{"stamper", self_path(), {"--gtest_filter=-*"}}}, policy, log);
    supervisor.start_all();
    const double deadline = monotonic_seconds() + 30.0;
    while (read_stamps(file).size() < static_cast<size_t>(starts) && monotonic_seconds() < deadline) {
      supervisor.poll();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    supervisor.stop_all();
  }
  ::unsetenv("WRC_TEST_STAMP_FILE");
  ::unsetenv("WRC_TEST_STAMP_SLEEP");
  log_text = log.str();
  std::vector<double> stamps = read_stamps(file);
  std::remove(file.c_str());
  return stamps;
}

// A child that exits at once, restarted 4 times with backoff_min 0.5 s, backoff_max 2 s: the
// supervisor decides the delays 0.5, 1, 2 (doubled twice) and 2 s (capped), and each interval
// between starts is at least its delay. 5.5 s of waiting.
TEST(SupervisorBackoff, MeasuredRestartsDoubleUpToTheCap) {
  ASSERT_FALSE(kIsStampChild);
  SupervisorPolicy policy;
  policy.backoff_min = 0.5;
  policy.backoff_max = 2.0;
  std::string log;
  const std::vector<double> t = supervised_starts(policy, 5, 0.0, log);
  ASSERT_GE(t.size(), 5u) << log;
  const double delays[4] = {0.5, 1.0, 2.0, 2.0};
  const std::vector<double> decided = logged_delays(log);
  ASSERT_GE(decided.size(), 4u) << log;
  for (size_t k = 0; k < 4; ++k) {
    const double interval = t[k + 1] - t[k];
    EXPECT_EQ(decided[k], delays[k]) << "restart #" << k + 1 << "\n" << log;
    EXPECT_GE(interval, delays[k]) << "restart #" << k + 1 << "\n" << log;
    std::cout << "[ measured ] restart #" << k + 1 << ": " << interval << " s after the previous start (delay "
              << delays[k] << " s, " << interval - delays[k] << " s on top)\n";
  }
}

// A child that runs 0.3 s, longer than stable_after = 0.2 s, counts as stable every time: each
// restart is decided backoff_min = 0.3 s after its death, never doubled (a doubling back-off
// would decide 0.6, 1.2, 2.4), and each interval between starts is at least 0.3 s of running +
// 0.3 s of delay. About 2.5 s.
TEST(SupervisorBackoff, StableRunsRestartAfterTheShortestDelay) {
  ASSERT_FALSE(kIsStampChild);
  SupervisorPolicy policy;
  policy.backoff_min = 0.3;
  policy.backoff_max = 4.0;
  policy.stable_after = 0.2;
  std::string log;
  const std::vector<double> t = supervised_starts(policy, 5, 0.3, log);
  ASSERT_GE(t.size(), 5u) << log;
  const std::vector<double> decided = logged_delays(log);
  ASSERT_GE(decided.size(), 4u) << log;
  for (size_t k = 0; k < 4; ++k) {
    const double interval = t[k + 1] - t[k];
    EXPECT_EQ(decided[k], 0.3) << "restart #" << k + 1 << "\n" << log;
    EXPECT_GE(interval, 0.6) << "restart #" << k + 1 << "\n" << log;
    std::cout << "[ measured ] restart #" << k + 1 << ": " << interval << " s after the previous start ("
              << interval - 0.6 << " s on top)\n";
  }
}

}  // namespace
