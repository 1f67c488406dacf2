// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The line wrc-dynamicsd logs when a run ends: its id, the simulated time it reached, why it
/// ended (only when a reason was given), its wall time and its counters. Strings from messages are
/// escaped and cut (bus/service/log_text.hpp).

#include <string>

#include "core/dynamics/run_counters.hpp"

namespace wrc::dynamics {

/// "wrc-dynamicsd: run <id> ended at t = <t> s[ (<reason>)] in <wall> s, <steps> steps, <restarts>
/// restarts, <queries> contact queries" (t [s], wall_time [s]); no parentheses when reason is
/// empty.
std::string run_end_log_line(const std::string& run_id, double t, const std::string& reason, double wall_time,
                             const RunCounters& counters);

}  // namespace wrc::dynamics
