#pragma once
/// @file
/// The run messages of wrc-dynamicsd and their library counterparts: run_command_t <-> RunSpec
/// (with model, geometry and swaps), WheelsetSnapshot -> wheelset_state_t, RunCounters ->
/// integrator_stats_t, the end of a run -> run_summary_t. No transport here.

#include <string>
#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/run_command_t.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"

namespace wrc::dynamics {

/// A swap at a given simulated time.
struct ScheduledSwap {
  double t = 0;       ///< [s]
  std::string model;  ///< model to swap to
};

/// Everything a START command says.
struct RunRequest {
  std::string run_id;
  std::string model;
  std::string instance;
  GeometrySpec geometry;
  bool in_process = false;
  RunSpec spec;
  double contact_timeout = 0.2;  ///< [s] per attempt
  int contact_retries = 3;       ///< [-] re-sends per attempt round
  double contact_wait = 10.0;    ///< [s] how long a run waits for a (restarted) contact service
  std::vector<ScheduledSwap> swaps;
};

/// The START command of request (header, request_id are the caller's).
/// Name of a run_status_t state code, as the summary JSON and the logs write it ("idle",
/// "running", "finished", "failed", "stopped"; "unknown" for any other code).
const char* run_state_name(std::int8_t state);

run_command_t to_message(const RunRequest& request);
/// @throws std::invalid_argument naming the first invalid field (unknown model, NaN, range).
RunRequest from_message(const run_command_t& command);

/// The state message of a snapshot at speed V (x = V t).
wheelset_state_t to_state_message(const WheelsetSnapshot& s, const std::string& run_id, double speed);
/// The counters message.
integrator_stats_t to_stats_message(const RunCounters& c, const std::string& run_id, double t, double wall_time);
/// The summary of a finished, failed or stopped simulation.
run_summary_t to_summary_message(WheelsetSimulation& simulation, const std::string& run_id, std::int64_t request_id,
                                 double wall_time);

}  // namespace wrc::dynamics
