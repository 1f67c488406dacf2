// wrc plot run: the paper's figures 5-6 for one or more runs: lateral displacement, the right
// contact point and the right normal force against time, from `wrc run --history` files (one curve
// per file, e.g. one-point and spline contact side by side).

#include <filesystem>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/plot/run_history.hpp"

namespace wrc::cli::plot {
namespace {

int run_run(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = image_option_specs("run.png");
  Options opt("plot run", "FILE.csv [FILE2.csv ...] [--out FILE]", specs, args, Positional::kAllowed);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe paper's figures 5-6: lateral displacement y, the right contact point (wheel profile\n"
                 "coordinate s_right) and the right normal force against time, one curve per history file\n"
                 "written by `wrc run --history FILE.csv`, labelled with its contact model(s).\n";
    return 0;
  }
  if (opt.positional().empty()) throw UsageError("give at least one history file (wrc run --history FILE.csv)");
  const ImageRequest image = image_from_options(opt, "run.png");
  GnuplotJob job;
  struct Curve {
    std::string file, label;
  };
  std::vector<Curve> curves;
  for (const std::string& path : opt.positional()) {
    const RunHistory history = read_run_history(path);
    const std::string name = format("run_%zu.dat", curves.size());
    auto out = job.open_data(name);
    out << "# t[s] y[m] s_right[m] normal_force_right[N]\n";
    for (size_t i = 0; i < history.t.size(); ++i)
      out << history.t[i] << " " << history.y[i] << " " << history.s_right[i] << " " << history.normal_force_right[i]
          << "\n";
    std::string models;
    for (const auto& m : history.models) models += (models.empty() ? "" : " → ") + m;
    const std::string file = std::filesystem::path(path).filename().string();
    curves.push_back({job.data_path(name), models.empty() ? file : models + " (" + file + ")"});
  }
  std::string names;
  for (const auto& c : curves) names += (names.empty() ? "" : ", ") + c.label;
  auto plot_column = [&](int column, double scale) {
    std::string line = "plot ";
    for (size_t i = 0; i < curves.size(); ++i)
      line += (i ? ", " : "") + plot::quoted(curves[i].file) + format(" using 1:($%d*%g) with lines lw 1.5 title ", column, scale) +
              plot::quoted(curves[i].label);
    return line + "\n";
  };
  std::string script = "set multiplot layout 3,1 title " + plot::quoted("Wheelset run: " + names) + "\n";
  script += "set grid\nset key top right\nset xlabel 'time t [s]'\n";
  script += "set ylabel 'lateral displacement y [mm]'\n" + plot_column(2, 1e3);
  script += "set ylabel 'right contact point s_right [mm]'\n" + plot_column(3, 1e3);
  script += "set ylabel 'right normal force [kN]'\n" + plot_column(4, 1e-3);
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"run", "lateral displacement, right contact point and force against time of wrc run --history files",
     run_run, 4}};

}  // namespace
}  // namespace wrc::cli::plot
