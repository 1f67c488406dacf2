// wrc plot bifurcation FILE.csv: the hunting bifurcation diagram of wrc bifurcation's CSV.

#include <iostream>

#include "cli/options.hpp"
#include "cli/plot/bifurcation_plot.hpp"
#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"

namespace wrc::cli::plot {
namespace {

int run_bifurcation_plot(const std::vector<std::string>& args) {
  const Options o("plot bifurcation", "FILE.csv [--out FILE]", image_option_specs("bifurcation.png"), args,
                  Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nDraws the hunting bifurcation diagram of a CSV of wrc bifurcation: the amplitude of y against\n"
                 "speed, the centred branch and the ramp-down's limit cycles, the linear and nonlinear critical\n"
                 "speeds (docs/bifurcation.md).\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("plot bifurcation: give one CSV file of wrc bifurcation");
  const std::string file = o.positional().front();
  sweep::CsvTable table;
  try {
    table = sweep::read_csv_file(file);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  const ImageRequest image = image_from_options(o, "bifurcation.png");
  try {
    draw_bifurcation(table, image, "wrc bifurcation: " + file);
  } catch (const std::runtime_error& e) {
    throw UsageError(file + ": " + e.what());
  }
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"bifurcation", "the hunting bifurcation diagram of wrc bifurcation's CSV", run_bifurcation_plot, 65}};

}  // namespace
}  // namespace wrc::cli::plot
