// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The plot of a sweep's CSV (`wrc plot sweep`, `wrc sweep --plot`): one result column against a
/// grid key, one line per value of another key (--by), finished runs only. A key whose values are
/// not all numbers (profile files, models) is drawn as categories in the grid's order.

#include <string>

#include "cli/plot/gnuplot_job.hpp"
#include "cli/sweep/sweep_table.hpp"

namespace wrc::cli::plot {

/// The column of table named name: its full header ("final_state.y [m]") or the name without the
/// unit ("final_state.y", "speed"). @throws UsageError naming what (the option) and the columns.
std::size_t sweep_column(const sweep::CsvTable& table, const std::string& name, const std::string& what);

/// Draws column y against column x, one line per value of column by (by: table.header.size() for
/// none). @throws std::runtime_error when no finished run has a value of y.
void draw_sweep(const sweep::CsvTable& table, std::size_t x, std::size_t y, std::size_t by, const ImageRequest& image,
                const std::string& title);

}  // namespace wrc::cli::plot
