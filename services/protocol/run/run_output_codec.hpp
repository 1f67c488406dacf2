// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a run publishes, in message form: WheelsetSnapshot -> wheelset_state_t, RunCounters ->
/// integrator_stats_t, the end of a run -> run_summary_t. No transport here.

#include <cstdint>
#include <string>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"

namespace wrc::protocol {

/// The run_status_t state code of a run's state (RUNNING, FINISHED, FAILED, STOPPED).
std::int8_t run_state_code(RunState state);

/// The state message of a snapshot of a run of wheelset w (x = V t + ahead [m], its place ahead of
/// a vehicle's reference point; Nadal's and Prud'homme's limits from its flange angle, friction and
/// load); wheelset: its index in a vehicle run.
wheelset_state_t to_state_message(const WheelsetSnapshot& s, const std::string& run_id, const WheelsetParameters& w,
                                  int wheelset = 0, double ahead = 0.0);
/// The counters message (every counter of run_counter_table(); t [s] and wall_time [s] as given).
integrator_stats_t to_stats_message(const RunCounters& c, const std::string& run_id, double t, double wall_time);
/// The counters of a counters message.
RunCounters from_stats_message(const integrator_stats_t& message);
/// The summary of a finished, failed or stopped simulation.
run_summary_t to_summary_message(WheelsetSimulation& simulation, const std::string& run_id, std::int64_t request_id,
                                 double wall_time);
/// The summary of a vehicle run: every wheelset in wheelsets, the first also in the lone
/// wheelset's fields.
run_summary_t to_summary_message(VehicleSimulation& simulation, const std::string& run_id, std::int64_t request_id,
                                 double wall_time);

}  // namespace wrc::protocol
