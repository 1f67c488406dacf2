// The process supervisor's restart back-off measured from the children themselves, not read from
// its log: each child appends the monotonic time at which it started to a file, and the intervals
// between those starts are checked against process_supervisor.hpp's policy (backoff_min, doubling
// per short-lived run up to backoff_max; backoff_min again after a run of stable_after or more).
//
// The child is this test binary itself: a static initialiser runs before gtest's main when
// WRC_TEST_STAMP_FILE is set in the environment, writes CLOCK_MONOTONIC there (the clock of
// bus::monotonic_seconds, which the supervisor's deadlines use), sleeps WRC_TEST_STAMP_SLEEP
// seconds if given, and exits 0.
//
// Bounds. Lower, strict: the supervisor schedules a restart `delay` after it saw the death, which
// is after the dead child wrote its stamp (and after its sleep), and the next child writes its
// stamp after being started, so an interval is never shorter than delay (+ sleep). Upper, loose:
// what comes on top is the child's exit, the supervisor's poll period (5 ms here), fork and exec
// with dynamic linking of this binary (a few ms unloaded): kSlack = 0.4 s allows a hundred times
// that for a loaded 2-core machine, and is still below the 0.5 s by which a back-off that doubled
// once too often (or not at all, or was not capped) would move an interval.
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

constexpr double kSlack = 0.4;  // [s] see the file comment

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
// intervals between its starts are the delays 0.5, 1, 2 (doubled twice) and 2 s (capped), each
// within [delay, delay + kSlack]. 5.5 s of waiting.
TEST(SupervisorBackoff, MeasuredRestartsDoubleUpToTheCap) {
  ASSERT_FALSE(kIsStampChild);
  SupervisorPolicy policy;
  policy.backoff_min = 0.5;
  policy.backoff_max = 2.0;
  std::string log;
  const std::vector<double> t = supervised_starts(policy, 5, 0.0, log);
  ASSERT_GE(t.size(), 5u) << log;
  const double delays[4] = {0.5, 1.0, 2.0, 2.0};
  for (size_t k = 0; k < 4; ++k) {
    const double interval = t[k + 1] - t[k];
    EXPECT_GE(interval, delays[k]) << "restart #" << k + 1 << "\n" << log;
    EXPECT_LE(interval, delays[k] + kSlack) << "restart #" << k + 1 << "\n" << log;
    std::cout << "[ measured ] restart #" << k + 1 << ": " << interval << " s after the previous start (delay "
              << delays[k] << " s)\n";
  }
}

// A child that runs 0.3 s, longer than stable_after = 0.2 s, counts as stable every time: each
// restart comes backoff_min = 0.3 s after its death, never doubled. Intervals between starts:
// 0.3 s of running + 0.3 s of delay, within [0.6, 0.6 + kSlack] for 4 restarts (a doubling back-off
// would give 0.9, 1.5, 2.7). About 2.5 s.
TEST(SupervisorBackoff, StableRunsRestartAfterTheShortestDelay) {
  ASSERT_FALSE(kIsStampChild);
  SupervisorPolicy policy;
  policy.backoff_min = 0.3;
  policy.backoff_max = 4.0;
  policy.stable_after = 0.2;
  std::string log;
  const std::vector<double> t = supervised_starts(policy, 5, 0.3, log);
  ASSERT_GE(t.size(), 5u) << log;
  for (size_t k = 0; k < 4; ++k) {
    const double interval = t[k + 1] - t[k];
    EXPECT_GE(interval, 0.6) << "restart #" << k + 1 << "\n" << log;
    EXPECT_LE(interval, 0.6 + kSlack) << "restart #" << k + 1 << "\n" << log;
    std::cout << "[ measured ] restart #" << k + 1 << ": " << interval << " s after the previous start\n";
  }
}

}  // namespace
