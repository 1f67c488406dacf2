// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The hunting bifurcation diagram of `wrc bifurcation`'s CSV (`wrc plot bifurcation`,
/// `wrc bifurcation --plot`): the amplitude of y against speed, the centred runs and the
/// ramp-down's stable cycles solid, the linear and the nonlinear critical speed marked.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli/plot/gnuplot_job.hpp"
#include "cli/sweep/sweep_table.hpp"

namespace wrc::cli::plot {

/// The header of the CSV that `wrc bifurcation` writes and draw_bifurcation reads.
const std::vector<std::string>& bifurcation_csv_header();

/// A diagram's runs sorted by what they show, each point (speed [m/s], amplitude of y [m]) in
/// increasing speed; keys: centred, centred-unsettled, grown (small starts), cycle (reaching the
/// flange root), tread-cycle, irregular (its envelope), cycle-unsettled, collapsed (ramp-down),
/// unstable, failed.
struct BifurcationPoints {
  std::map<std::string, std::vector<std::pair<double, double>>> points;
  double linear = -1;            ///< linear critical speed [m/s], -1: none found
  double linear_frequency = 0;   ///< its frequency [Hz]
  double nonlinear = -1;         ///< nonlinear critical speed [m/s], -1: none found
};

/// The runs of table (a CSV with bifurcation_csv_header()).
/// @throws std::runtime_error when the table is not such a CSV.
BifurcationPoints classify_bifurcation(const sweep::CsvTable& table);

/// Draws table (a CSV with bifurcation_csv_header()) into image.
/// @throws std::runtime_error when the table is not such a CSV or has no run to draw.
void draw_bifurcation(const sweep::CsvTable& table, const ImageRequest& image, const std::string& title);

/// One diagram of several in one picture, and its label (a contact model's name, say).
struct LabelledBifurcation {
  std::string label;
  sweep::CsvTable table;
};

/// Draws several diagrams into one image, one colour each: the stable cycles of each ramp-down
/// (tread and flange), the small starts that grew, the failed runs, and each diagram's nonlinear
/// and linear critical speed marked (the centred runs, all at 0, are left out).
/// @throws std::runtime_error when a table is not such a CSV or has no run, for more than 8
/// diagrams, or when none has a cycle or a failed run to draw.
void draw_bifurcations(const std::vector<LabelledBifurcation>& diagrams, const ImageRequest& image,
                       const std::string& title);

}  // namespace wrc::cli::plot
