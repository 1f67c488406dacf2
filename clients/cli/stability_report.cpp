// SPDX-License-Identifier: Apache-2.0
#include "cli/stability_report.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "cli/plot/gnuplot_job.hpp"
#include "cli/plot/plot_options.hpp"

namespace wrc::cli {

void write_stability_csv(const std::string& path, const std::vector<StabilityScanRow>& scan) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  const bool bodies = !scan.empty() && !scan.front().bodies.empty();
  out.precision(10);
  out << "speed [m/s],real [1/s],imag [rad/s],frequency [Hz],damping_ratio [-],kind [-]," << (bodies ? "body [-]," : "")
      << "least_damped [-]\n";
  for (const StabilityScanRow& l : scan) {
    for (size_t i = 0; i < l.modes.size(); ++i) {
      const StabilityMode& m = l.modes[i];
      out << l.speed << "," << m.eigenvalue.real() << "," << m.eigenvalue.imag() << "," << m.frequency() << ","
          << m.damping_ratio() << "," << mode_kind_name(m.kind) << ","
          << (bodies ? l.bodies[i] + "," : std::string()) << (i == 0 ? 1 : 0) << "\n";
    }
  }
}

void draw_stability(const std::string& path, const std::vector<StabilityScanRow>& scan, const CriticalSpeed& critical,
                    const std::string& title) {
  const plot::ImageRequest image = plot::image_request(path, 1400, 700);
  plot::GnuplotJob job;
  {
    auto locus = job.open_data("locus.dat");
    auto largest = job.open_data("largest.dat");
    locus << "# real[1/s] frequency[Hz] speed[m/s]\n";
    largest << "# speed[m/s] largest_real[1/s]\n";
    for (const StabilityScanRow& l : scan) {
      // The spin mode's real eigenvalue lies far to the left (hundreds of 1/s): the locus shows
      // the lateral (and vertical) modes, the CSV has every eigenvalue.
      for (const StabilityMode& m : l.modes)
        if (m.kind != ModeKind::kSpin) locus << m.eigenvalue.real() << " " << m.eigenvalue.imag() / (2 * M_PI) << " " << l.speed << "\n";
      largest << l.speed << " " << l.modes.front().eigenvalue.real() << "\n";
    }
  }
  std::string script = "set multiplot layout 1,2 title " + plot::quoted(title) + "\n";
  script += "set grid\nset xlabel 'real part [1/s]'\nset ylabel 'imaginary part / 2 pi [Hz]'\n"
            "set cblabel 'speed [m/s]'\nset palette rgb 33,13,10\nset xzeroaxis\nset arrow from 0, graph 0 to 0, graph 1 nohead dt 2\n"
            "set title 'eigenvalues (root locus, spin mode left out)'\n";
  script += "plot " + plot::quoted(job.data_path("locus.dat")) + " using 1:2:3 with points pt 7 ps 0.5 palette notitle\n";
  script += "unset arrow\nset xlabel 'speed [m/s]'\nset ylabel 'largest real part [1/s]'\nunset cblabel\n"
            "set title 'least damped mode'\nset yzeroaxis\n";
  if (critical.found)
    script += plot::format("set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lc rgb 'red'\n"
                           "set label %s at %.9g, graph 0.92 left offset 1,0\n",
                           critical.speed, critical.speed,
                           plot::quoted(plot::format("V_c = %.2f m/s, %.2f Hz", critical.speed, critical.frequency)).c_str(),
                           critical.speed);
  script += "plot " + plot::quoted(job.data_path("largest.dat")) + " using 1:2 with linespoints pt 7 ps 0.5 lw 1.5 notitle\n";
  script += "unset multiplot\n";
  job.render(script, image);
}

}  // namespace wrc::cli
