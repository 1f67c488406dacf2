// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What `wrc run` writes: the summary as JSON (final state, counters of run_counter_table(),
/// swaps, the parameters of run_parameter_table(), the maxima of docs/run-quantities.md) and the
/// state history as CSV.

#include <map>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "protocol/run/run_command_codec.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"

namespace wrc::cli {

/// The summary JSON of a run asked for by request; key: the geometry key.
nlohmann::json summary_json(const run_summary_t& summary, const protocol::RunRequest& request, const std::string& key);

/// Writes the summary JSON to path. @throws std::runtime_error when it cannot.
void write_summary(const std::string& path, const nlohmann::json& summary);

/// A run's states by simulated time [s] and wheelset (its index in a vehicle run; the lone
/// wheelset: 0).
using StateHistory = std::map<std::pair<double, int>, wheelset_state_t>;

/// Writes the states by simulated time [s] and wheelset as CSV (SI units), every header
/// "name [unit]" (docs/cli.md lists the columns). @throws std::runtime_error when it cannot.
void write_history(const std::string& path, const StateHistory& history);

}  // namespace wrc::cli
