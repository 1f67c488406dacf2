// SPDX-License-Identifier: Apache-2.0
// wrc plot run: the paper's figures 5-6 for one or more runs: lateral displacement, the right
// contact point and the right normal force against time, from `wrc run --history` files (one curve
// per file, e.g. one-point and spline contact side by side); with --forces what engineers read off
// the runs against the distance travelled: Y/Q of both wheels with Nadal's limit, the axle's sum of
// Y with Prud'homme's limit and T gamma of both wheels (docs/run-quantities.md).

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/plot/run_history.hpp"

namespace wrc::cli::plot {
namespace {

int run_run(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = image_option_specs("run.png");
  specs.push_back({"--forces", false,
                   "Y/Q with Nadal's limit, sum Y with Prud'homme's limit and T gamma against the distance", ""});
  Options opt("plot run", "FILE.csv [FILE2.csv ...] [--out FILE]", specs, args, Positional::kAllowed);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe paper's figures 5-6: lateral displacement y, the right contact point (wheel profile\n"
                 "coordinate s_right) and the right normal force against time, one curve per history file\n"
                 "written by `wrc run --history FILE.csv`, labelled with its contact model(s).\n"
                 "--forces: Y/Q of both wheels with Nadal's limit, the axle's track-shift force sum Y with\n"
                 "Prud'homme's limit (+-) and the wear number T gamma of both wheels, against the distance\n"
                 "travelled (docs/run-quantities.md).\n";
    return 0;
  }
  if (opt.positional().empty()) throw UsageError("give at least one history file (wrc run --history FILE.csv)");
  const ImageRequest image = image_from_options(opt, "run.png");
  GnuplotJob job;
  const bool forces = opt.has("--forces");
  struct Curve {
    std::string file, label;
  };
  std::vector<Curve> curves;
  for (const std::string& path : opt.positional()) {
    const RunHistory history = read_run_history(path);
    const std::string name = format("run_%zu.dat", curves.size());
    auto out = job.open_data(name);
    if (forces) {
      const RunHistory::Forces& f = history.forces;
      if (f.distance.empty())
        throw std::runtime_error("'" + path + "' has no force columns (distance, y_over_q_left, ...): write it again "
                                 "with this wrc run --history");
      out << "# distance[m] y_over_q_left[-] y_over_q_right[-] nadal_limit[-] track_shift_force[N] "
             "prudhomme_limit[N] wear_number_left[N] wear_number_right[N]\n";
      for (size_t i = 0; i < f.distance.size(); ++i)
        out << f.distance[i] << " " << f.y_over_q_left[i] << " " << f.y_over_q_right[i] << " " << f.nadal_limit[i]
            << " " << f.track_shift_force[i] << " " << f.prudhomme_limit[i] << " " << f.wear_number_left[i] << " "
            << f.wear_number_right[i] << "\n";
    } else {
      out << "# t[s] y[m] s_right[m] normal_force_right[N]\n";
      for (size_t i = 0; i < history.t.size(); ++i)
        out << history.t[i] << " " << history.y[i] << " " << history.s_right[i] << " " << history.normal_force_right[i]
            << "\n";
    }
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
  if (forces) {
    // Each quantity of both wheels (left solid, right dashed) and its limit from the first file.
    auto plot_wheels = [&](int left, int right, double scale) {
      std::string line = "plot ";
      for (size_t i = 0; i < curves.size(); ++i) {
        const std::string file = plot::quoted(curves[i].file);
        line += (i ? ", " : "") + file + format(" using 1:($%d*%g) with lines lw 1.5 lc %zu title ", left, scale, i + 1) +
                plot::quoted(curves[i].label + ", left") + ", " + file +
                format(" using 1:($%d*%g) with lines lw 1.5 dt 2 lc %zu title ", right, scale, i + 1) +
                plot::quoted(curves[i].label + ", right");
      }
      return line;
    };
    const std::string first = plot::quoted(curves.front().file);
    std::string script = "set multiplot layout 3,1 title " + plot::quoted("Wheel-rail forces: " + names) + "\n";
    script += "set grid\nset key top right\nset xlabel 'distance travelled [m]'\n";
    script += "set ylabel 'Y/Q [-]'\n" + plot_wheels(2, 3, 1.0) + ", " + first +
              " using 1:4 with lines lw 2 lc 'red' title 'Nadal limit'\n";
    std::string shift = "plot ";
    for (size_t i = 0; i < curves.size(); ++i)
      shift += (i ? ", " : "") + plot::quoted(curves[i].file) +
               format(" using 1:($5*1e-3) with lines lw 1.5 lc %zu title ", i + 1) + plot::quoted(curves[i].label);
    script += "set ylabel 'track-shift force sum Y [kN]'\n" + shift + ", " + first +
              " using 1:($6*1e-3) with lines lw 2 lc 'red' title 'Prud''homme limit', " + first +
              " using 1:(-$6*1e-3) with lines lw 2 lc 'red' notitle\n";
    script += "set ylabel 'wear number T gamma [N]'\n" + plot_wheels(7, 8, 1.0) + "\n";
    script += "unset multiplot\n";
    job.render(script, image);
    return report_written(image);
  }
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
    {"run", "lateral displacement, right contact point and force against time of wrc run --history files "
            "(--forces: Y/Q, sum Y and T gamma against the distance)",
     run_run, 4}};

}  // namespace
}  // namespace wrc::cli::plot
