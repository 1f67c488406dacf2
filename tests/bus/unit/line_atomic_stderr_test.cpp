// SPDX-License-Identifier: Apache-2.0
// std::cerr made line-atomic: lines written in many pieces by several threads at once reach
// standard error whole, one line per write, none cut by another; a line longer than the atomic
// size arrives complete, and what a thread leaves without '\n' is written when it ends.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bus/process/line_atomic_stderr.hpp"

namespace {

// Points file descriptor 2 at a new file for the lifetime of the object; contents() reads it.
class CapturedStderr {
 public:
  CapturedStderr() {
    char path[] = "/tmp/wrc_line_atomic_XXXXXX";
    const int fd = ::mkstemp(path);
    path_ = path;
    ::close(fd);
    log_ = ::open(path, O_WRONLY | O_APPEND);
    saved_ = ::dup(STDERR_FILENO);
    ::dup2(log_, STDERR_FILENO);
  }
  ~CapturedStderr() {
    restore();
    std::remove(path_.c_str());
  }
  void restore() {
    if (saved_ < 0) return;
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    ::close(log_);
    saved_ = -1;
  }
  bool ok() const { return log_ >= 0 && saved_ >= 0; }
  std::string contents() const {
    std::ifstream in(path_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  std::string path_;
  int log_ = -1, saved_ = -1;
};

TEST(LineAtomicStderr, LongLinesAndUnfinishedLinesArrive) {
  wrc::bus::make_stderr_line_atomic();
  CapturedStderr captured;
  ASSERT_TRUE(captured.ok());
  const std::string long_line(5000, 'x');  // longer than one atomic write (4096 bytes)
  std::thread([&] { std::cerr << long_line << "\n" << "unfinished"; }).join();
  captured.restore();
  EXPECT_EQ(captured.contents(), long_line + "\nunfinished");
}

TEST(LineAtomicStderr, PiecewiseLinesFromThreadsArriveWhole) {
  char path[] = "/tmp/wrc_line_atomic_XXXXXX";
  const int fd = ::mkstemp(path);
  ASSERT_GE(fd, 0);
  ::close(fd);
  const int log = ::open(path, O_WRONLY | O_APPEND);
  ASSERT_GE(log, 0);
  std::cerr.flush();
  const int saved = ::dup(STDERR_FILENO);
  ASSERT_GE(::dup2(log, STDERR_FILENO), 0);

  wrc::bus::make_stderr_line_atomic();
  wrc::bus::make_stderr_line_atomic();  // a second call changes nothing
  constexpr int kThreads = 4, kLines = 500;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([t] {
      for (int i = 0; i < kLines; ++i) std::cerr << "thread " << t << " line " << i << " piece a" << " piece b" << "\n";
    });
  }
  for (auto& th : threads) th.join();

  ::dup2(saved, STDERR_FILENO);
  ::close(saved);
  ::close(log);
  std::ifstream in(path);
  std::string line;
  std::vector<int> next(kThreads, 0);
  int lines = 0;
  while (std::getline(in, line)) {
    int t = -1, i = -1;
    char a[16] = {0}, b[16] = {0};
    ASSERT_EQ(std::sscanf(line.c_str(), "thread %d line %d piece %15s piece %15s", &t, &i, a, b), 4) << "cut line: " << line;
    ASSERT_TRUE(t >= 0 && t < kThreads) << line;
    EXPECT_EQ(i, next[t]++) << "lines of one thread out of order: " << line;
    EXPECT_EQ(std::string(a) + std::string(b), "ab") << line;
    ++lines;
  }
  EXPECT_EQ(lines, kThreads * kLines);
  std::remove(path);
}

}  // namespace
