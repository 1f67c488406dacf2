// SPDX-License-Identifier: Apache-2.0
// wrc plot bifurcation FILE.csv [FILE2.csv ...]: the hunting bifurcation diagram of wrc
// bifurcation's CSV, or several diagrams (one per contact model, say) in one picture.

#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/options.hpp"
#include "cli/plot/bifurcation_plot.hpp"
#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"

namespace wrc::cli::plot {
namespace {

int run_bifurcation_plot(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = image_option_specs("bifurcation.png");
  specs.push_back({"--labels", true, "with several files: one label per file, comma-separated", "the files' names"});
  specs.push_back({"--title", true, "the picture's title", "wrc bifurcation: the files"});
  const Options o("plot bifurcation", "FILE.csv [FILE2.csv ...] [--labels A,B,...] [--out FILE]", specs, args,
                  Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nDraws the hunting bifurcation diagram of a CSV of wrc bifurcation: the amplitude of y against\n"
                 "speed, the centred branch and the ramp-down's limit cycles, the linear and nonlinear critical\n"
                 "speeds (docs/bifurcation.md). With several files, one colour per file: each ramp-down's stable\n"
                 "cycles, small starts that grew, failed runs and both critical speeds, e.g. the four contact\n"
                 "models of one wheelset (labels: the files' names without folder and extension, or --labels).\n";
    return 0;
  }
  const std::vector<std::string>& files = o.positional();
  if (files.empty()) throw UsageError("plot bifurcation: give one or more CSV files of wrc bifurcation");
  std::vector<std::string> labels;
  if (o.has("--labels")) {
    std::stringstream list(o.text("--labels"));
    for (std::string label; std::getline(list, label, ',');) labels.push_back(label);
    if (labels.size() != files.size())
      throw UsageError("--labels: '" + o.text("--labels") + "' names " + std::to_string(labels.size()) +
                       " diagrams for " + std::to_string(files.size()) + " files");
  } else {
    for (const std::string& f : files) labels.push_back(std::filesystem::path(f).stem().string());
  }
  std::vector<LabelledBifurcation> diagrams;
  std::string joined;
  for (std::size_t i = 0; i < files.size(); ++i) {
    LabelledBifurcation d;
    d.label = labels[i];
    try {
      d.table = sweep::read_csv_file(files[i]);
    } catch (const std::exception& e) {
      throw UsageError(e.what());
    }
    diagrams.push_back(std::move(d));
    joined += (i ? ", " : "") + files[i];
  }
  const ImageRequest image = image_from_options(o, "bifurcation.png");
  const std::string title = o.has("--title") ? o.text("--title") : "wrc bifurcation: " + joined;
  try {
    if (diagrams.size() == 1)
      draw_bifurcation(diagrams.front().table, image, title);
    else
      draw_bifurcations(diagrams, image, title);
  } catch (const std::runtime_error& e) {
    throw UsageError(joined + ": " + e.what());
  }
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"bifurcation", "the hunting bifurcation diagram of wrc bifurcation's CSV (several: one picture)",
     run_bifurcation_plot, 65}};

}  // namespace
}  // namespace wrc::cli::plot
