// SPDX-License-Identifier: Apache-2.0
// wrc plot conicity: the equivalent conicity (harmonic linearisation of the rolling-radius
// difference of the exact rigid-wheelset geometry) against the amplitude of the lateral motion.

#include <cmath>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/conicity.hpp"
#include "core/numerics/inclusive_range.hpp"

namespace wrc::cli::plot {
namespace {

int run_conicity(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--a-from", true, "smallest amplitude [m], in (0, 0.02]", "2.5e-4", NumberRange{1e-7, 0.02}});
  specs.push_back({"--a-to", true, "largest amplitude [m], in (0, 0.02]", "0.01", NumberRange{1e-7, 0.02}});
  specs.push_back({"--a-step", true, "amplitude step [m]", "2.5e-4", NumberRange{1e-7, 0.02}});
  specs.push_back({"--samples", true, "points on the period for the Fourier integral", "256", NumberRange{8, 100000}});
  for (const auto& spec : image_option_specs("conicity.png")) specs.push_back(spec);
  Options opt("plot conicity", "[--a-from A] [--a-to B] [--a-step H] [--out FILE] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nlambda_e(A) = 1/(2 pi A) * integral over one period of delta_r(A sin t) sin t dt against the\n"
                 "amplitude A, delta_r from the exact rigid-wheelset geometry (as wrc conicity).\n";
    return 0;
  }
  const double a_from = opt.number("--a-from");
  const double a_to = opt.number("--a-to");
  const double step = opt.number("--a-step");
  const int samples = opt.integer("--samples");
  if (!(a_to >= a_from)) throw UsageError(format("--a-to %g is below --a-from %g", a_to, a_from));
  const long count = inclusive_range_count(a_from, a_to, step);
  if (count > 10000) throw UsageError(format("--a-step %g gives more than 10000 amplitudes", step));
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const ImageRequest image = image_from_options(opt, "conicity.png");

  const RigidWheelsetSolver solver(geometry);
  GnuplotJob job;
  {
    auto out = job.open_data("conicity.dat");
    out << "# amplitude[m] equivalent_conicity[-]\n";
    for (long i = 0; i < count; ++i) {
      const double a = a_from + static_cast<double>(i) * step;
      out << a << " " << equivalent_conicity(solver, a, samples) << "\n";
    }
  }
  const std::string title = "Equivalent conicity (harmonic linearisation): " + geometry_title(spec);
  std::string script = "set title " + plot::quoted(title) + "\n";
  script += "set grid\nset key top left\nset xlabel 'amplitude of the lateral motion A [mm]'\n"
            "set ylabel 'equivalent conicity λe [-]'\nset yrange [0:*]\n";
  script += "plot " + plot::quoted(job.data_path("conicity.dat")) +
            " using ($1*1e3):2 with linespoints pt 7 ps 0.6 lw 1.5 title 'λe'\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{{"conicity", "equivalent conicity against amplitude", run_conicity, 5}};

}  // namespace
}  // namespace wrc::cli::plot
