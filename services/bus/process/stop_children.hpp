// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Stopping child processes the one way wrc does it everywhere (`wrc launch`, the services `wrc
/// query` starts, benchmarks): SIGTERM, a grace period for a clean exit (a service drains and sends
/// its DRAINING heartbeat), then SIGKILL for whatever is still running, and every child reaped.

#include <sys/types.h>

#include <functional>
#include <vector>

namespace wrc::bus {

/// How one child ended.
struct StoppedChild {
  pid_t pid = -1;       ///< the child (its process group with whole_group)
  int wait_status = 0;  ///< as waitpid() gives it; meaningful when reaped
  bool reaped = false;  ///< false when it was no child of ours any more (ECHILD: reaped elsewhere)
  bool killed = false;  ///< it outlived the grace period and was sent SIGKILL
};

/// Callbacks of stop_children (either may be empty).
struct StopHooks {
  std::function<void(pid_t)> before_kill;                ///< a child outlived the grace period
  std::function<void(const StoppedChild&)> on_reaped;    ///< a child ended (in the order they end)
};

/// Sends SIGTERM to every pid (> 0; others are skipped), to its process group when whole_group,
/// waits up to grace [s] for them to end (polling every 10 ms), sends SIGKILL to those still
/// running and reaps them. With whole_group every group also gets a SIGKILL once its leader has
/// ended (whatever the child left behind). Returns one entry per stopped pid, in the given order.
std::vector<StoppedChild> stop_children(const std::vector<pid_t>& pids, double grace, bool whole_group = false,
                                        const StopHooks& hooks = {});

}  // namespace wrc::bus
