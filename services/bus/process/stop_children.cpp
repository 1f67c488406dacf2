// SPDX-License-Identifier: Apache-2.0
#include "bus/process/stop_children.hpp"

#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

#include "bus/transport/clock.hpp"

namespace wrc::bus {

std::vector<StoppedChild> stop_children(const std::vector<pid_t>& pids, double grace, bool whole_group,
                                        const StopHooks& hooks) {
  std::vector<StoppedChild> children;
  for (pid_t pid : pids) {
    if (pid <= 0) continue;
    ::kill(whole_group ? -pid : pid, SIGTERM);
    StoppedChild child;
    child.pid = pid;
    children.push_back(child);
  }
  std::vector<bool> done(children.size(), false);
  // Reaps what has ended (every child when block); true while any is still running.
  auto reap = [&](bool block) {
    bool running = false;
    for (std::size_t i = 0; i < children.size(); ++i) {
      if (done[i]) continue;
      StoppedChild& child = children[i];
      int status = 0;
      const pid_t r = ::waitpid(child.pid, &status, block ? 0 : WNOHANG);
      if (r == child.pid || (r < 0 && errno == ECHILD)) {
        child.reaped = r == child.pid;
        child.wait_status = child.reaped ? status : 0;
        if (whole_group) ::kill(-child.pid, SIGKILL);  // anything the child left in its group
        done[i] = true;
        if (hooks.on_reaped) hooks.on_reaped(child);
      } else {
        running = true;
      }
    }
    return running;
  };
  const double deadline = monotonic_seconds() + grace;
  while (reap(false) && monotonic_seconds() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (std::size_t i = 0; i < children.size(); ++i) {
    if (done[i]) continue;
    if (hooks.before_kill) hooks.before_kill(children[i].pid);
    children[i].killed = true;
    ::kill(whole_group ? -children[i].pid : children[i].pid, SIGKILL);
  }
  reap(true);
  return children;
}

}  // namespace wrc::bus
