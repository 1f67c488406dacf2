// SPDX-License-Identifier: Apache-2.0
#include "bus/process/process_supervisor.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

#include "bus/process/stop_children.hpp"
#include "bus/transport/clock.hpp"

namespace wrc::bus {

std::string describe_exit(int wait_status) {
  std::ostringstream out;
  if (WIFEXITED(wait_status)) {
    out << "exited with status " << WEXITSTATUS(wait_status);
  } else if (WIFSIGNALED(wait_status)) {
    const int sig = WTERMSIG(wait_status);
    const char* name = ::strsignal(sig);
    out << "killed by signal " << sig << " (" << (name != nullptr ? name : "?") << ")";
  } else {
    out << "ended with wait status " << wait_status;
  }
  return out.str();
}

ProcessSupervisor::ProcessSupervisor(std::vector<ChildSpec> children, SupervisorPolicy policy,
                                     std::ostream& log)
    : policy_(policy), log_(log) {
  for (auto& spec : children) {
    ChildState state;
    state.spec = std::move(spec);
    children_.push_back(std::move(state));
  }
}

ProcessSupervisor::~ProcessSupervisor() { stop_all(); }

void ProcessSupervisor::start_all() {
  for (auto& child : children_) start(child);
}

void ProcessSupervisor::start(ChildState& child) {
  std::vector<std::string> words;
  words.push_back(child.spec.path);
  words.insert(words.end(), child.spec.args.begin(), child.spec.args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    log_ << "launch: cannot fork for " << child.spec.name << ": " << std::strerror(errno)
         << "; retrying in " << policy_.backoff_max << " s" << std::endl;
    child.restart_at = monotonic_seconds() + policy_.backoff_max;
    return;
  }
  if (pid == 0) {
    // child: own process group, die with the supervisor, default signal handling, exec
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(1);  // supervisor already gone
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGCHLD, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::execv(argv[0], argv.data());
    const std::string msg = "launch: cannot execute " + words[0] + ": " + std::strerror(errno) + "\n";
    [[maybe_unused]] auto n = ::write(2, msg.data(), msg.size());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here, so that the group exists before we ever signal it
  child.pid = pid;
  child.started_at = monotonic_seconds();
  child.last_heartbeat = -1.0;
  child.nonce = 0;
  std::ostringstream command;
  for (const auto& w : words) command << (command.tellp() > 0 ? " " : "") << w;
  log_ << "launch: started " << child.spec.name << " (pid " << pid << "): " << command.str() << std::endl;
}

void ProcessSupervisor::on_exit(ChildState& child, int wait_status, double now, bool hung) {
  const double ran = now - child.started_at;
  child.failures_in_row = ran >= policy_.stable_after ? 1 : child.failures_in_row + 1;
  double delay = policy_.backoff_min;
  for (int i = 1; i < child.failures_in_row && delay < policy_.backoff_max; ++i) delay *= 2.0;
  delay = std::min(delay, policy_.backoff_max);
  if (hung && child.failures_in_row <= 1) delay = 0.0;  // its clients already wait: no back-off the first time
  ++child.restarts;
  child.restart_at = now + delay;
  log_ << "launch: " << child.spec.name << " (pid " << child.pid << ") " << describe_exit(wait_status)
       << " after " << std::fixed << std::setprecision(1) << ran << " s; restart #" << child.restarts
       << " in " << std::setprecision(2) << delay << " s" << std::defaultfloat << std::endl;
  child.pid = -1;
}

void ProcessSupervisor::heartbeat_seen(pid_t pid, std::uint64_t nonce, double period, double seen_at) {
  if (pid <= 0 || !(period > 0.0)) return;
  for (auto& child : children_) {
    if (child.pid != pid || seen_at <= child.last_heartbeat || seen_at < child.started_at) continue;
    if (child.nonce == 0) {
      child.nonce = nonce;
      child.heartbeat_period = period;
    } else if (nonce != child.nonce) {
      continue;  // another sender naming this pid
    }
    child.last_heartbeat = seen_at;
  }
}

bool process_stopped(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(in, text)) return false;
  // "pid (comm) S ...": comm may hold blanks and parentheses, the state follows the last ')'.
  const auto close = text.rfind(')');
  if (close == std::string::npos || close + 2 >= text.size()) return false;
  const char state = text[close + 2];
  return state == 'T' || state == 't';
}

const char* ProcessSupervisor::hang_reason(const ChildState& child, double now) const {
  if (child.last_heartbeat < 0.0) return nullptr;
  const double silent = now - child.last_heartbeat;
  if (silent > policy_.unconfirmed_hang_periods * child.heartbeat_period) return "silent, not stopped";
  if (silent > policy_.hang_periods * child.heartbeat_period && process_stopped(child.pid)) return "stopped";
  return nullptr;
}

void ProcessSupervisor::kill_hung(ChildState& child, double now, const char* why) {
  ++child.hangs;
  log_ << "launch: " << child.spec.name << " (pid " << child.pid << ") sent no heartbeat for " << std::fixed
       << std::setprecision(2) << now - child.last_heartbeat << " s (" << std::setprecision(1)
       << (now - child.last_heartbeat) / child.heartbeat_period << " periods of " << std::setprecision(2)
       << child.heartbeat_period << " s) and is " << why << ": killing it (SIGKILL)" << std::defaultfloat
       << std::endl;
  ::kill(-child.pid, SIGKILL);
  ::kill(child.pid, SIGKILL);
  int status = 0;
  pid_t r = 0;
  for (int i = 0; i < 200 && (r = ::waitpid(child.pid, &status, WNOHANG)) == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (r != child.pid) {
    log_ << "launch: " << child.spec.name << " (pid " << child.pid << ") not reaped 1 s after SIGKILL" << std::endl;
    return;  // reaped by a later poll()
  }
  on_exit(child, status, monotonic_seconds(), /*hung=*/true);
}

void ProcessSupervisor::poll() {
  const double now = monotonic_seconds();
  // Time this supervisor itself was away (its loop behind, descheduled) is nobody's silence:
  // every child's last heartbeat moves on by it.
  if (last_poll_ >= 0.0 && now - last_poll_ > policy_.own_delay) {
    for (auto& child : children_)
      if (child.last_heartbeat >= 0.0) child.last_heartbeat += now - last_poll_;
  }
  last_poll_ = now;
  for (auto& child : children_) {
    if (child.pid > 0) {
      int status = 0;
      const pid_t r = ::waitpid(child.pid, &status, WNOHANG);
      if (r == child.pid) {
        on_exit(child, status, now);
      } else if (const char* why = hang_reason(child, now)) {
        kill_hung(child, now, why);
      }
    }
    if (child.pid < 0 && child.restart_at <= now) start(child);
  }
}

void ProcessSupervisor::stop_all() {
  std::vector<pid_t> pids;
  std::vector<ChildState*> running;
  for (auto& child : children_) {
    if (child.pid > 0) {
      pids.push_back(child.pid);
      running.push_back(&child);
    }
  }
  if (pids.empty()) return;
  auto child_of = [&](pid_t pid) -> ChildState& {
    for (ChildState* c : running) {
      if (c->pid == pid) return *c;
    }
    return *running.front();  // not reached: every pid is one of running
  };
  StopHooks hooks;
  hooks.before_kill = [&](pid_t pid) {
    log_ << "launch: " << child_of(pid).spec.name << " (pid " << pid << ") did not stop within " << policy_.grace
         << " s, sending SIGKILL" << std::endl;
  };
  hooks.on_reaped = [&](const StoppedChild& stopped) {
    log_ << "launch: stopped " << child_of(stopped.pid).spec.name << " (pid " << stopped.pid
         << "): " << (stopped.reaped ? describe_exit(stopped.wait_status) : std::string("already reaped"))
         << std::endl;
  };
  stop_children(pids, policy_.grace, /*whole_group=*/true, hooks);
  for (ChildState* c : running) c->pid = -1;
}

}  // namespace wrc::bus
