// SPDX-License-Identifier: Apache-2.0
// wrc plot irregularities FILE.csv: the four channels of a track-irregularity file (alignment,
// vertical level, cross-level, gauge; docs/track.md) against the distance, one panel each.

#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "core/track/track_irregularity_file.hpp"

namespace wrc::cli::plot {
namespace {

int run_irregularities(const std::vector<std::string>& args) {
  auto specs = image_option_specs("irregularities.png");
  Options opt("plot irregularities", "FILE.csv [--out FILE]", specs, args, Positional::kAllowed);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nFILE.csv: s [m] and the channels alignment, vertical_level, cross_level, gauge in m or mm (as\n"
                 "wrc irregularities writes and wrc run --irregularities reads). Drawn in mm against s in m.\n";
    return 0;
  }
  if (opt.positional().size() != 1) throw UsageError("plot irregularities takes one FILE.csv");
  const std::string path = opt.positional().front();
  const TrackIrregularity t = read_track_irregularity_file(path);
  const ImageRequest image = image_from_options(opt, "irregularities.png");
  GnuplotJob job;
  {
    auto out = job.open_data("irregularities.dat");
    out << "# s[m] alignment[m] vertical_level[m] cross_level[m] gauge[m]\n";
    for (std::size_t i = 0; i < t.distances().size(); ++i) {
      out << t.distances()[i];
      for (IrregularityChannel c : kIrregularityChannels) out << " " << t.samples(c)[i];
      out << "\n";
    }
  }
  std::string script = "set multiplot layout 4,1 title " + plot::quoted("Track irregularities: " + path) + "\n";
  script += "set grid\nunset key\n";
  int column = 2;
  for (IrregularityChannel c : kIrregularityChannels) {
    const std::string name = irregularity_channel_name(c);
    script += "set ylabel " + plot::quoted(name + " [mm]") + "\n";
    script += column == 5 ? "set xlabel 'distance along the track s [m]'\n" : "unset xlabel\n";
    script += "plot " + plot::quoted(job.data_path("irregularities.dat")) + " using 1:($" + std::to_string(column) +
              "*1e3) with lines lw 1.2\n";
    ++column;
  }
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"irregularities", "the four channels of a track-irregularity file against the distance", run_irregularities, 9}};

}  // namespace
}  // namespace wrc::cli::plot
