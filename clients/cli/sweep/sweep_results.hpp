// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a sweep extracts from each run (--extract), as columns of its CSV, and the run of one grid
/// point into its row. Groups: `final` (every final_state value of the run summary and t_end),
/// `maxima` (every number under run_quantities: the largest |Y/Q| per wheel, |sum Y|, T gamma and
/// Hertz pressure per wheel, with the limits; docs/run-quantities.md), `counters` (every counter of
/// core/dynamics/run_counter_table.hpp), `critical_speed` (the linear critical speed and its
/// frequency at the run's parameters, core/dynamics/linear_stability.hpp, as `wrc stability`);
/// or single paths into the summary JSON (`run_quantities.y_over_q.left.t`, `parameters.speed`).
/// A column's name is its path and unit, "final_state.y [m]".

#include <string>
#include <vector>

#include "cli/sweep/sweep_definition.hpp"
#include "cli/sweep/sweep_table.hpp"

namespace wrc::cli {

/// The --extract groups, in their order.
const std::vector<std::string>& extract_groups();

/// The speeds [m/s] of --critical-speeds FROM:TO:STEP. @throws UsageError naming the bad value.
std::vector<double> critical_speed_scan(const std::string& text);

/// One result column.
struct ResultColumn {
  std::string path;  ///< into the run summary JSON, or "critical_speed" / "critical_frequency"
  std::string unit;
  std::string name() const { return path + " [" + unit + "]"; }
};

/// The columns of the extract items (groups or paths) for runs like example.
/// @throws UsageError naming an item that is no group and no path of a summary's value.
std::vector<ResultColumn> result_columns(const std::vector<std::string>& extract, const protocol::RunRequest& example);

/// The row of grid point `point` (its values, one per axis): the run in this process and what the
/// columns take from it. A run that fails, or cannot start, is a row with status failed and the
/// reason in its error; a failing critical-speed scan too. Never throws for the run's sake.
sweep::SweepRow run_sweep_point(const SweepDefinition& definition, const std::vector<ResultColumn>& columns,
                                std::size_t point, const std::vector<std::string>& values);

}  // namespace wrc::cli
