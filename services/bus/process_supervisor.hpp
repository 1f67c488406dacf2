#pragma once
/// @file
/// Starts and supervises child processes for `wrc launch`: a child that dies is restarted after
/// an exponential back-off, with one log line saying which child, its pid, how it ended and when
/// it restarts; stop_all() ends every child (SIGTERM, then SIGKILL after a grace period).
/// Each child runs in its own process group (so that its own children are stopped with it) and
/// gets SIGTERM when the supervisor dies (PR_SET_PDEATHSIG), so no process is left behind even
/// if the supervisor is killed.

#include <sys/types.h>

#include <ostream>
#include <string>
#include <vector>

namespace wrc::bus {

/// A process to supervise.
struct ChildSpec {
  std::string name;               ///< name used in log lines
  std::string path;               ///< executable path
  std::vector<std::string> args;  ///< arguments (without argv[0])
};

/// Restart and stop timing.
struct SupervisorPolicy {
  double backoff_min = 0.25;   ///< [s] delay before the first restart
  double backoff_max = 8.0;    ///< [s] largest delay (doubling from backoff_min)
  double stable_after = 10.0;  ///< [s] a child that ran this long restarts after backoff_min again
  double grace = 3.0;          ///< [s] wait after SIGTERM before SIGKILL
};

/// State of one supervised child.
struct ChildState {
  ChildSpec spec;
  pid_t pid = -1;             ///< running pid, -1 while waiting for a restart
  int restarts = 0;           ///< restarts so far
  int failures_in_row = 0;    ///< consecutive short-lived runs (drives the back-off)
  double started_at = 0.0;    ///< [s] monotonic start of the current run
  double restart_at = 0.0;    ///< [s] monotonic time of the pending restart
};

/// "exited with status N" or "killed by signal N (NAME)" for a waitpid status.
std::string describe_exit(int wait_status);

/// Supervisor of a set of children; single-threaded, driven by poll().
class ProcessSupervisor {
 public:
  /// log: where the supervisor writes its lines (prefixed "launch: ").
  ProcessSupervisor(std::vector<ChildSpec> children, SupervisorPolicy policy, std::ostream& log);
  ~ProcessSupervisor();
  ProcessSupervisor(const ProcessSupervisor&) = delete;
  ProcessSupervisor& operator=(const ProcessSupervisor&) = delete;

  /// Starts every child once.
  void start_all();
  /// Reaps children that ended, logs why and schedules their restart; starts those whose
  /// back-off has passed. Call every few tens of milliseconds.
  void poll();
  /// SIGTERM to every child's process group, waits up to the grace period, SIGKILL to the rest,
  /// reaps all. Logs each stop. Safe to call twice.
  void stop_all();
  /// Current children.
  const std::vector<ChildState>& children() const { return children_; }

 private:
  void start(ChildState& child);
  void on_exit(ChildState& child, int wait_status, double now);

  std::vector<ChildState> children_;
  SupervisorPolicy policy_;
  std::ostream& log_;
};

}  // namespace wrc::bus
