// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Starts and supervises child processes for `wrc launch`: a child that dies is restarted after
/// an exponential back-off, with one log line saying which child, its pid, how it ended and when
/// it restarts; a child whose heartbeats stop is killed with a line saying so and restarted at
/// once: after hang_periods of its heartbeat period when its process state confirms it is stopped
/// (SIGSTOP), after unconfirmed_hang_periods otherwise (a lossy network loses heartbeats, the
/// child's own identity decides which heartbeats count) (the back-off
/// applies from its second failure in a row); stop_all() ends every child (SIGTERM, then
/// SIGKILL after a grace period). The owner feeds heartbeats in with heartbeat_seen().
/// Each child runs in its own process group (so that its own children are stopped with it) and
/// gets SIGTERM when the supervisor dies (PR_SET_PDEATHSIG), so no process is left behind even
/// if the supervisor is killed.

#include <sys/types.h>

#include <cstdint>
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
  /// [-] heartbeat periods of silence after which a child that has sent heartbeats and is
  /// stopped (SIGSTOP, or held by a tracer: its process state says so) is hung. 2 periods plus the
  /// restart stays within the 3 periods after which clients call it dead.
  double hang_periods = 2.0;
  /// [-] heartbeat periods of silence after which a child is killed although its process state
  /// does not say it is stopped (deadlocked, or its heartbeats lost on the way). A lossy network
  /// loses single heartbeats, so silence alone must be long: 20 periods in a row are lost with
  /// probability 0.05^20 at 5 % loss.
  double unconfirmed_hang_periods = 20.0;
  /// [s] a pause between two polls longer than this is the supervisor's own delay (its loop
  /// behind on its queue, or descheduled), and does not count as silence of the children.
  double own_delay = 0.25;
};

/// State of one supervised child.
struct ChildState {
  ChildSpec spec;
  pid_t pid = -1;             ///< running pid, -1 while waiting for a restart
  int restarts = 0;           ///< restarts so far
  int failures_in_row = 0;    ///< consecutive short-lived runs (drives the back-off)
  double started_at = 0.0;    ///< [s] monotonic start of the current run
  double restart_at = 0.0;    ///< [s] monotonic time of the pending restart
  double last_heartbeat = -1.0;   ///< [s] monotonic arrival of its last heartbeat, < 0 = none yet
  double heartbeat_period = 0.0;  ///< [s] period its first heartbeat declared
  std::uint64_t nonce = 0;        ///< [-] sender nonce of its first heartbeat: its identity, 0 = none yet
  int hangs = 0;                  ///< times it was killed for silence
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
  /// A heartbeat of process pid, signed by sender nonce, with the declared period [s] arrived at
  /// monotonic time seen_at [s]. The first heartbeat naming a child's pid after its start fixes
  /// the child's identity (nonce) and period; later heartbeats count only with that nonce, so a
  /// message that merely names the pid steers nothing. Ignored when pid is not a running child or
  /// the heartbeat is older than one known.
  void heartbeat_seen(pid_t pid, std::uint64_t nonce, double period, double seen_at);
  /// SIGTERM to every child's process group, waits up to the grace period, SIGKILL to the rest,
  /// reaps all. Logs each stop. Safe to call twice.
  void stop_all();
  /// Current children.
  const std::vector<ChildState>& children() const { return children_; }

 private:
  void start(ChildState& child);
  void on_exit(ChildState& child, int wait_status, double now, bool hung = false);
  /// Kills child (whole group, SIGKILL), reaps it and schedules its restart; why: the log's reason.
  void kill_hung(ChildState& child, double now, const char* why);
  /// Whether the silence of child at now makes it hung, and why (nullptr: not hung).
  const char* hang_reason(const ChildState& child, double now) const;

  std::vector<ChildState> children_;
  SupervisorPolicy policy_;
  std::ostream& log_;
  double last_poll_ = -1.0;  // [s] monotonic time of the previous poll(), < 0 = none yet
};

/// Whether the process pid is stopped (state T, by a signal, or t, by a tracer) by its
/// /proc/<pid>/stat; false when that cannot be read.
bool process_stopped(pid_t pid);

}  // namespace wrc::bus
