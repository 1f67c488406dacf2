#pragma once
/// @file
/// The hunting bifurcation diagram of `wrc bifurcation`'s CSV (`wrc plot bifurcation`,
/// `wrc bifurcation --plot`): the amplitude of y against speed, the centred runs and the
/// ramp-down's stable cycles solid, the linear and the nonlinear critical speed marked.

#include <string>
#include <vector>

#include "cli/plot/gnuplot_job.hpp"
#include "core/sweep/sweep_table.hpp"

namespace wrc::cli::plot {

/// The header of the CSV that `wrc bifurcation` writes and draw_bifurcation reads.
const std::vector<std::string>& bifurcation_csv_header();

/// Draws table (a CSV with bifurcation_csv_header()) into image.
/// @throws std::runtime_error when the table is not such a CSV or has no run to draw.
void draw_bifurcation(const sweep::CsvTable& table, const ImageRequest& image, const std::string& title);

}  // namespace wrc::cli::plot
