// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// One `wrc run` as a session: the services the run needs started (wrc-dynamicsd, the contact
/// services of its models, wrc-geometryd for those that need data) when none runs, the START
/// sent until acknowledged (and again, from the start, when the process running it is lost: its
/// statuses and heartbeats stop), the progress shown, the history and the summary collected, written
/// and reported, and the services started for it stopped.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "cli/run_outputs.hpp"
#include "cli/service_starter.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"
#include "wrc/wheelset_states_t.hpp"

namespace wrc::cli {

class RunSession {
 public:
  /// Joins the bus of options (and waits kServiceDiscoveryTime [s] for heartbeats) for request.
  RunSession(const Options& options, protocol::RunRequest request);
  ~RunSession();

  /// Starts every service the run needs that is not running.
  void start_services();
  /// Sends the run and follows it to its summary (a stop is sent on SIGINT / SIGTERM). When the
  /// wrc-dynamicsd running it goes silent (no status for 2 s and its heartbeats missed), the run is
  /// sent again to the instance that takes over (one this command started is started again); the
  /// summary counts it (run_resends).
  /// @throws std::runtime_error when the dynamics goes silent for kSilenceLimit [s].
  const run_summary_t& run();
  /// Writes the summary (--summary) and the history (--history), reports the run on stderr and
  /// stops the services started for it; the exit code: 0 when the run finished.
  int finish();

 private:
  const Options& options_;
  protocol::RunRequest request_;
  std::string key_;  ///< geometry key of the request
  CommandBus session_;
  /// Starts the wrc-dynamicsd again when this command started it and it has ended.
  void restart_own_dynamics();
  /// Starts a wrc-dynamicsd for this run unless one is READY (ensure_service), as its own.
  void start_own_dynamics();

  std::vector<std::unique_ptr<StartedService>> started_;
  StartedService* own_dynamics_ = nullptr;  ///< the wrc-dynamicsd this command started, if any
  long resends_ = 0;                        ///< times the run was sent again to a new dynamics process
  StateHistory history_;
  std::optional<run_summary_t> summary_;
};

}  // namespace wrc::cli
