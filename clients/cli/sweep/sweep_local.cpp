// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_local.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "cli/progress_bar.hpp"

namespace wrc::cli {
namespace {

volatile sig_atomic_t g_interrupted = 0;

void on_signal(int) { g_interrupted = 1; }

// SIGINT and SIGTERM set g_interrupted (no SA_RESTART: a wait returns with EINTR); the previous
// handlers come back at the end of the scope.
class InterruptScope {
 public:
  InterruptScope() {
    g_interrupted = 0;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~InterruptScope() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

pid_t start_point(const SweepWork& work, std::size_t point, const std::string& self) {
  std::vector<std::string> args{self};
  for (const std::string& a : run_point_arguments(work, std::to_string(point))) args.push_back(a);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = work.log_path(point);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("sweep: cannot start a run: ") + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);  // a terminal's Ctrl-C reaches the sweep, which stops its runs itself
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  ::setpgid(pid, pid);  // here too: the group exists before the sweep may signal it
  return pid;
}

std::string exit_text(int status) {
  if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("signal ") + strsignal(WTERMSIG(status));
  return "status " + std::to_string(status);
}

}  // namespace

std::string own_executable() {
  char buffer[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) throw std::runtime_error("sweep: cannot find this program's path (/proc/self/exe)");
  return std::string(buffer, static_cast<std::size_t>(n));
}

std::vector<std::string> run_point_arguments(const SweepWork& work, const std::string& point) {
  return {"sweep", "--run-point", point, "--work-dir", work.directory()};
}

bool run_points_locally(const SweepWork& work, const sweep::SweepLayout& layout, const std::vector<std::size_t>& points,
                        int jobs, const std::function<void(const sweep::SweepRow&)>& on_row) {
  const InterruptScope scope;
  const std::string self = own_executable();
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, done = 0, failed = 0;
  ProgressBar bar("sweep");
  auto show = [&] {
    bar.update(static_cast<long>(done), static_cast<long>(points.size()),
               std::to_string(done) + "/" + std::to_string(points.size()) + " runs, " + std::to_string(failed) +
                   " failed, " + std::to_string(running.size()) + " running");
  };
  show();
  while ((next < points.size() || !running.empty()) && !g_interrupted) {
    while (next < points.size() && static_cast<int>(running.size()) < jobs && !g_interrupted) {
      running[start_point(work, points[next], self)] = points[next];
      ++next;
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("sweep: waiting for the runs: ") + std::strerror(errno));
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;  // not one of ours
    const std::size_t point = it->second;
    running.erase(it);
    std::optional<sweep::SweepRow> row;
    try {
      row = work.read_row(point, layout);
    } catch (const std::invalid_argument& e) {
      std::cerr << "\nsweep: " << e.what() << "\n";
    }
    if (!row) {
      row = sweep::SweepRow{};
      row->point = point;
      row->status = "failed";
      row->results.assign(layout.result_count(), "");
      row->error = "the run's process ended with " + exit_text(status) + " and no result (its log: " +
                   work.log_path(point) + ")";
      row->wall_time = "";
    }
    if (row->status == "finished") {
      std::error_code ec;
      std::filesystem::remove(work.log_path(point), ec);  // a failed run keeps its log
    } else {
      ++failed;
    }
    ++done;
    on_row(*row);
    show();
  }
  if (g_interrupted) {
    for (const auto& [pid, point] : running) ::kill(-pid, SIGTERM);
    for (const auto& [pid, point] : running) {
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    std::cerr << "\nsweep: interrupted; stopped " << running.size() << " running run(s)\n";
    return false;
  }
  bar.finish();
  return true;
}

}  // namespace wrc::cli
