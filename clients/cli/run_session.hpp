#pragma once
/// @file
/// One `wrc run` as a session: the services the run needs started (wrc-dynamicsd, the contact
/// services of its models, wrc-geometryd for those that need data) when none runs, the START
/// sent until acknowledged, the progress shown, the history and the summary collected, written
/// and reported, and the services started for it stopped.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "cli/service_starter.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"

namespace wrc::cli {

class RunSession {
 public:
  /// Joins the bus of options (and waits kServiceDiscoveryTime [s] for heartbeats) for request.
  RunSession(const Options& options, protocol::RunRequest request);
  ~RunSession();

  /// Starts every service the run needs that is not running.
  void start_services();
  /// Sends the run and follows it to its summary (a stop is sent on SIGINT / SIGTERM).
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
  std::vector<std::unique_ptr<StartedService>> started_;
  std::map<double, wheelset_state_t> history_;
  std::optional<run_summary_t> summary_;
};

}  // namespace wrc::cli
