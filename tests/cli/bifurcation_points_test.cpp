// SPDX-License-Identifier: Apache-2.0
// The runs of a `wrc bifurcation` CSV sorted by what they show (classify_bifurcation,
// cli/plot/bifurcation_plot.hpp): an irregular run of the ramp-down is drawn as its own series at
// its envelope (the amplitude column), an irregular small start as one that grew; limit cycles
// split by their largest contact angle into tread and flange cycles.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/plot/bifurcation_plot.hpp"

namespace wrc::cli::plot {
namespace {

// A row of the CSV: branch, speed [m/s], state, amplitude [m], largest contact angle [rad].
std::vector<std::string> row(const std::string& branch, double speed, const std::string& state, double amplitude,
                             double angle) {
  return {branch, std::to_string(speed), state, std::to_string(amplitude), "0", "0", "11", "1",
          std::to_string(angle), angle > 0.5 ? "1" : "0", "0.005", "4.5", "100", ""};
}

TEST(BifurcationPoints, IrregularMotionIsItsOwnSeriesAtItsEnvelope) {
  sweep::CsvTable table;
  table.header = bifurcation_csv_header();
  table.rows = {row("centred", 110, "irregular", 6.9e-3, 1.22), row("ramp-down", 110, "irregular", 6.7e-3, 1.22),
                row("ramp-down", 100, "irregular", 6.6e-3, 1.22), row("ramp-down", 90, "limit-cycle", 2.9e-3, 0.09),
                row("ramp-down", 80, "limit-cycle", 2.0e-3, 0.6), row("ramp-down", 50, "centred", 1e-7, 0.02)};
  const BifurcationPoints p = classify_bifurcation(table);
  using Points = std::vector<std::pair<double, double>>;
  EXPECT_EQ(p.points.at("irregular"), (Points{{100, 6.6e-3}, {110, 6.7e-3}}));
  EXPECT_EQ(p.points.at("grown"), (Points{{110, 6.9e-3}}));
  EXPECT_EQ(p.points.at("tread-cycle"), (Points{{90, 2.9e-3}}));
  EXPECT_EQ(p.points.at("cycle"), (Points{{80, 2.0e-3}}));
  EXPECT_EQ(p.points.at("collapsed"), (Points{{50, 0.0}}));  // a centred run is drawn at 0
  EXPECT_EQ(p.points.count("cycle-unsettled"), 0u);
}

}  // namespace
}  // namespace wrc::cli::plot
