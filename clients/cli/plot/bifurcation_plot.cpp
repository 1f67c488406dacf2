#include "cli/plot/bifurcation_plot.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "cli/plot/plot_options.hpp"

namespace wrc::cli::plot {

const std::vector<std::string>& bifurcation_csv_header() {
  static const std::vector<std::string> header{
      "branch [-]",           "speed [m/s]",        "state [-]",          "amplitude [m]",
      "mean [m]",             "yaw_amplitude [rad]", "frequency [Hz]",    "growth [-]",
      "largest_contact_angle [rad]", "flange_contact [-]", "start_y [m]", "simulated_time [s]",
      "wall_time [s]",        "message [-]"};
  return header;
}

void draw_bifurcation(const sweep::CsvTable& table, const ImageRequest& image, const std::string& title) {
  if (table.header != bifurcation_csv_header())
    throw std::runtime_error("not a CSV of wrc bifurcation (its header differs from: branch [-], speed [m/s], ...)");
  // Column indices by the header above.
  constexpr std::size_t kBranch = 0, kSpeed = 1, kState = 2, kAmplitude = 3, kFrequency = 6, kAngle = 8;
  // Cycles whose largest contact angle stays below 0.2 rad (11 deg) stay on the tread (S1002 on
  // UIC60: below 0.1 rad there, 0.4 rad and more at the flange root, 1.2 rad on the flank): a
  // branch of their own.
  constexpr double kTreadAngle = 0.2;
  std::map<std::string, std::vector<std::pair<double, double>>> points;  // by branch
  double linear = -1, linear_f = 0, nonlinear = -1;
  for (const auto& row : table.rows) {
    const std::string& branch = row[kBranch];
    const double v = std::strtod(row[kSpeed].c_str(), nullptr);
    if (branch == "linear-critical") {
      linear = v;
      linear_f = std::strtod(row[kFrequency].c_str(), nullptr);
      continue;
    }
    if (branch == "nonlinear-critical") {
      nonlinear = v;
      continue;
    }
    if (branch == "unstable") {
      points["unstable"].push_back({v, std::strtod(row[kAmplitude].c_str(), nullptr)});
      continue;
    }
    if (row[kState] == "failed") {
      points["failed"].push_back({v, std::strtod(row[kAmplitude].c_str(), nullptr)});
      continue;
    }
    const double a = std::strtod(row[kAmplitude].c_str(), nullptr);
    const std::string& state = row[kState];
    const bool oscillating = state == "limit-cycle" || state == "growing";
    std::string key;
    if (branch == "centred")
      key = state == "centred" ? "centred" : oscillating ? "grown" : "centred-unsettled";
    else
      key = state == "limit-cycle" ? (std::strtod(row[kAngle].c_str(), nullptr) > kTreadAngle ? "cycle" : "tread-cycle")
            : oscillating ? "cycle-unsettled"
                          : "collapsed";
    points[key].push_back({v, state == "centred" ? 0.0 : a});
  }
  std::size_t total = 0;
  for (auto& [key, pts] : points) total += pts.size();
  if (total == 0) throw std::runtime_error("no run to draw");
  GnuplotJob job;
  struct Style {
    const char* key;
    const char* with;
    const char* title;
  };
  const Style styles[] = {
      {"centred", "linespoints lw 2 pt 7 ps 0.8 lc rgb '#1f77b4'", "small start: decays to the centred state"},
      {"centred-unsettled", "points pt 6 ps 1.2 lc rgb '#1f77b4'", "small start: still decaying at the end"},
      {"grown", "points pt 9 ps 1.5 lc rgb '#1f77b4'", "small start: grew into the cycle (centred state unstable)"},
      {"cycle", "linespoints lw 2 pt 5 ps 0.8 lc rgb '#d62728'", "ramp-down: stable cycle reaching the flange (root)"},
      {"tread-cycle", "linespoints lw 2 pt 5 ps 0.8 lc rgb '#ff7f0e'", "ramp-down: stable cycle on the tread"},
      {"cycle-unsettled", "points pt 4 ps 1.2 lc rgb '#d62728'", "ramp-down: still growing at the end"},
      {"collapsed", "points pt 4 ps 1.5 lc rgb '#2ca02c'", "ramp-down: cycle collapsed (centred or decaying)"},
      {"unstable", "linespoints dt 2 lw 2 pt 6 ps 0.8 lc rgb '#9467bd'", "unstable cycle (separatrix estimate)"},
      {"failed", "points pt 2 ps 1.5 lc rgb 'black'", "failed (amplitude when it stopped)"},
  };
  std::string plots;
  for (const Style& s : styles) {
    auto it = points.find(s.key);
    if (it == points.end() || it->second.empty()) continue;
    std::sort(it->second.begin(), it->second.end());
    const std::string data = std::string(s.key) + ".dat";
    {
      auto out = job.open_data(data);
      out << "# speed[m/s] amplitude[mm]\n";
      for (const auto& [v, a] : it->second) out << v << " " << a * 1e3 << "\n";
    }
    plots += std::string(plots.empty() ? "plot " : ", ") + quoted(job.data_path(data)) + " using 1:2 with " + s.with +
             " title " + quoted(s.title);
  }
  std::string script = "set title " + quoted(title) + " noenhanced\nset grid\nset key top left noenhanced box opaque\n";
  script += "set xlabel 'speed [m/s]'\nset ylabel 'amplitude of y, half peak-to-peak [mm]'\nset yrange [0:*]\n";
  if (linear > 0)
    script += format("set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2 lw 1.5 lc rgb '#1f77b4'\n"
                     "set label %s at %.9g, graph 0.55 left rotate by 90 offset -0.8,0 tc rgb '#1f77b4' noenhanced\n",
                     linear, linear, quoted(format("linear V_c = %.2f m/s, %.2f Hz", linear, linear_f)).c_str(), linear);
  if (nonlinear > 0)
    script += format("set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 3 lw 1.5 lc rgb '#d62728'\n"
                     "set label %s at %.9g, graph 0.25 left rotate by 90 offset -0.8,0 tc rgb '#d62728' noenhanced\n",
                     nonlinear, nonlinear, quoted(format("nonlinear V_nl = %.2f m/s", nonlinear)).c_str(), nonlinear);
  job.render(script + plots + "\n", image);
}

}  // namespace wrc::cli::plot
