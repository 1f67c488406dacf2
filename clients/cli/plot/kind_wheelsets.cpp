// SPDX-License-Identifier: Apache-2.0
// wrc plot wheelsets: every wheelset of a vehicle run (`wrc run --vehicle FILE --history F.csv`, or
// a `wrc record` log of it) against the distance each has travelled along the track (its own
// distance: the leading wheelset enters a curve first): its lateral displacement and its angle of
// attack (its yaw from its own track tangent), one curve per wheelset.

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/plot/run_history.hpp"

namespace wrc::cli::plot {
namespace {

int run_wheelsets(const std::vector<std::string>& args) {
  const std::vector<OptionSpec> specs = image_option_specs("wheelsets.png");
  Options opt("plot wheelsets", "FILE.csv [--out FILE]", specs, args, Positional::kAllowed);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nEvery wheelset of a vehicle run against the distance it has travelled along the track: its\n"
                 "lateral displacement y and its angle of attack (yaw from its own track tangent), one curve per\n"
                 "wheelset, from `wrc run --vehicle FILE --history FILE.csv` (or a `wrc record` log of the run).\n";
    return 0;
  }
  if (opt.positional().size() != 1) throw UsageError("give one history file of a vehicle run (wrc run --history FILE.csv)");
  const std::string path = opt.positional().front();
  const ImageRequest image = image_from_options(opt, "wheelsets.png");
  const std::map<int, RunHistory> wheelsets = read_wheelset_histories(path);
  GnuplotJob job;
  std::string displacement = "plot ", attack = "plot ";
  for (const auto& [index, history] : wheelsets) {
    const RunHistory::Forces& f = history.forces;
    if (f.distance.empty() || history.yaw.empty() || std::isnan(history.yaw.front()))
      throw std::runtime_error("'" + path + "' has no distance or yaw column: write it again with this wrc run --history");
    const std::string name = format("wheelset_%d.dat", index);
    auto out = job.open_data(name);
    out << "# distance[m] y[m] yaw[rad]\n";
    for (size_t i = 0; i < history.t.size(); ++i) out << f.distance[i] << " " << history.y[i] << " " << history.yaw[i] << "\n";
    const std::string file = plot::quoted(job.data_path(name));
    const std::string title = plot::quoted(format("wheelset %d", index + 1));
    const std::string sep = index == wheelsets.begin()->first ? "" : ", ";
    displacement += sep + file + " using 1:($2*1e3) with lines lw 1.5 title " + title;
    attack += sep + file + " using 1:($3*1e3) with lines lw 1.5 title " + title;
  }
  const std::string name = std::filesystem::path(path).filename().string();
  std::string script = "set multiplot layout 2,1 title " +
                       plot::quoted(format("Wheelsets of a vehicle run (%zu): ", wheelsets.size()) + name) + "\n";
  script += "set grid\nset key top right\nset xlabel 'distance along the track [m]'\n";
  script += "set ylabel 'lateral displacement y [mm]'\n" + displacement + "\n";
  script += "set ylabel 'angle of attack [mrad]'\n" + attack + "\n";
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"wheelsets", "every wheelset's lateral displacement and angle of attack against the distance (a vehicle run)",
     run_wheelsets, 8}};

}  // namespace
}  // namespace wrc::cli::plot
