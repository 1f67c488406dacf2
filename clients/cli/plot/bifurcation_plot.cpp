// SPDX-License-Identifier: Apache-2.0
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

BifurcationPoints classify_bifurcation(const sweep::CsvTable& table) {
  if (table.header != bifurcation_csv_header())
    throw std::runtime_error("not a CSV of wrc bifurcation (its header differs from: branch [-], speed [m/s], ...)");
  // Column indices by the header above.
  constexpr std::size_t kBranch = 0, kSpeed = 1, kState = 2, kAmplitude = 3, kFrequency = 6, kAngle = 8;
  // Cycles whose largest contact angle stays below 0.2 rad (11 deg) stay on the tread (S1002 on
  // UIC60: below 0.1 rad there, 0.4 rad and more at the flange root, 1.2 rad on the flank): a
  // branch of their own.
  constexpr double kTreadAngle = 0.2;
  BifurcationPoints out;
  for (const auto& row : table.rows) {
    const std::string& branch = row[kBranch];
    const double v = std::strtod(row[kSpeed].c_str(), nullptr);
    if (branch == "linear-critical") {
      out.linear = v;
      out.linear_frequency = std::strtod(row[kFrequency].c_str(), nullptr);
      continue;
    }
    if (branch == "nonlinear-critical") {
      out.nonlinear = v;
      continue;
    }
    if (branch == "unstable") {
      out.points["unstable"].push_back({v, std::strtod(row[kAmplitude].c_str(), nullptr)});
      continue;
    }
    if (row[kState] == "failed") {
      out.points["failed"].push_back({v, std::strtod(row[kAmplitude].c_str(), nullptr)});
      continue;
    }
    const double a = std::strtod(row[kAmplitude].c_str(), nullptr);
    const std::string& state = row[kState];
    const bool oscillating = state == "limit-cycle" || state == "growing" || state == "irregular";
    std::string key;
    if (branch == "centred")
      key = state == "centred" ? "centred" : oscillating ? "grown" : "centred-unsettled";
    else
      key = state == "limit-cycle" ? (std::strtod(row[kAngle].c_str(), nullptr) > kTreadAngle ? "cycle" : "tread-cycle")
            : state == "irregular" ? "irregular"
            : oscillating          ? "cycle-unsettled"
                                   : "collapsed";
    out.points[key].push_back({v, state == "centred" ? 0.0 : a});
  }
  for (auto& [key, pts] : out.points) std::sort(pts.begin(), pts.end());
  return out;
}

namespace {

std::size_t point_count(const BifurcationPoints& p) {
  std::size_t total = 0;
  for (const auto& [key, pts] : p.points) total += pts.size();
  return total;
}

// Writes pts as "speed [m/s] amplitude [mm]" into the job's data file name; returns its plot source.
std::string write_points(const GnuplotJob& job, const std::string& name,
                         const std::vector<std::pair<double, double>>& pts) {
  {
    auto out = job.open_data(name);
    out << "# speed[m/s] amplitude[mm]\n";
    for (const auto& [v, a] : pts) out << v << " " << a * 1e3 << "\n";
  }
  return quoted(job.data_path(name)) + " using 1:2";
}

// Appends a series to plots ("plot A, B, ..."): the points' source, its style and its key title.
void add_series(std::string& plots, const std::string& source, const std::string& with, const std::string& title) {
  plots += std::string(plots.empty() ? "plot " : ", ") + source + " with " + with + " title " + quoted(title);
}

// A vertical line at speed v [m/s] with a label at height [graph fraction].
std::string speed_marker(double v, const char* dash, const std::string& colour, double height, const std::string& text) {
  return format("set arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt %s lw 1.5 lc rgb '%s'\n"
                "set label %s at %.9g, graph %.3f left rotate by 90 offset -0.8,0 tc rgb '%s' noenhanced\n",
                v, v, dash, colour.c_str(), quoted(text).c_str(), v, height, colour.c_str());
}

const char* const kAxes =
    "set grid\nset key top left noenhanced box opaque\n"
    "set xlabel 'speed [m/s]'\nset ylabel 'amplitude of y, half peak-to-peak [mm]'\nset yrange [0:*]\n";

}  // namespace

void draw_bifurcation(const sweep::CsvTable& table, const ImageRequest& image, const std::string& title) {
  BifurcationPoints p = classify_bifurcation(table);
  if (point_count(p) == 0) throw std::runtime_error("no run to draw");
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
      {"irregular", "linespoints dt 3 lw 2 pt 13 ps 1.2 lc rgb '#8c564b'",
       "ramp-down: irregular motion persisting (its largest cycle)"},
      {"cycle-unsettled", "points pt 4 ps 1.2 lc rgb '#d62728'", "ramp-down: still growing at the end"},
      {"collapsed", "points pt 4 ps 1.5 lc rgb '#2ca02c'", "ramp-down: cycle collapsed (centred or decaying)"},
      {"unstable", "linespoints dt 2 lw 2 pt 6 ps 0.8 lc rgb '#9467bd'", "unstable cycle (separatrix estimate)"},
      {"failed", "points pt 2 ps 1.5 lc rgb 'black'", "failed (amplitude when it stopped)"},
  };
  std::string plots;
  for (const Style& s : styles) {
    auto it = p.points.find(s.key);
    if (it == p.points.end() || it->second.empty()) continue;
    add_series(plots, write_points(job, std::string(s.key) + ".dat", it->second), s.with, s.title);
  }
  std::string script = "set title " + quoted(title) + " noenhanced\n" + kAxes;
  if (p.linear > 0)
    script += speed_marker(p.linear, "2", "#1f77b4", 0.55, format("linear V_c = %.2f m/s, %.2f Hz", p.linear, p.linear_frequency));
  if (p.nonlinear > 0)
    script += speed_marker(p.nonlinear, "3", "#d62728", 0.25, format("nonlinear V_nl = %.2f m/s", p.nonlinear));
  job.render(script + plots + "\n", image);
}

void draw_bifurcations(const std::vector<LabelledBifurcation>& diagrams, const ImageRequest& image,
                       const std::string& title) {
  static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                         "#e377c2", "#7f7f7f"};
  constexpr std::size_t kMost = sizeof(kColours) / sizeof(kColours[0]);
  if (diagrams.empty()) throw std::runtime_error("no diagram to draw");
  if (diagrams.size() > kMost)
    throw std::runtime_error(format("%zu diagrams; one picture holds at most %zu", diagrams.size(), kMost));
  GnuplotJob job;
  std::string script = "set title " + quoted(title) + " noenhanced\n" + kAxes, plots;
  for (std::size_t d = 0; d < diagrams.size(); ++d) {
    const LabelledBifurcation& diagram = diagrams[d];
    const BifurcationPoints p = classify_bifurcation(diagram.table);
    if (point_count(p) == 0) throw std::runtime_error(diagram.label + ": no run to draw");
    const std::string colour = kColours[d];
    // The persisting motions of the ramp-down (tread and flange cycles, irregular motion) together,
    // and what failed.
    std::vector<std::pair<double, double>> cycles;
    for (const char* key : {"cycle", "tread-cycle", "irregular"}) {
      auto it = p.points.find(key);
      if (it != p.points.end()) cycles.insert(cycles.end(), it->second.begin(), it->second.end());
    }
    std::sort(cycles.begin(), cycles.end());
    auto add = [&](const std::string& name, const std::vector<std::pair<double, double>>& pts, const std::string& with,
                   const std::string& text) {
      if (!pts.empty())
        add_series(plots, write_points(job, format("%zu-", d) + name + ".dat", pts), with + " lc rgb '" + colour + "'",
                   text);
    };
    const bool irregular = p.points.count("irregular") > 0;
    std::string text = diagram.label + (irregular ? ": stable cycles, irregular motion" : ": stable cycles");
    if (p.nonlinear > 0) text += format(", V_nl = %.2f m/s", p.nonlinear);
    if (p.linear > 0) text += format(", V_c = %.2f m/s", p.linear);
    add("cycles", cycles, "linespoints lw 2 pt 5 ps 0.8", text);
    auto grown = p.points.find("grown");
    if (grown != p.points.end()) add("grown", grown->second, "points pt 9 ps 1.5", diagram.label + ": small start grew");
    auto failed = p.points.find("failed");
    if (failed != p.points.end())
      add("failed", failed->second, "points pt 2 ps 1.5", diagram.label + ": failed (amplitude when it stopped)");
    const double label_height = 0.65 - 0.12 * static_cast<double>(d);  // [graph fraction], one step per diagram
    if (p.nonlinear > 0)
      script += speed_marker(p.nonlinear, "3", colour, label_height, format("%s V_nl", diagram.label.c_str()));
    if (p.linear > 0) script += speed_marker(p.linear, "2", colour, label_height, format("%s V_c", diagram.label.c_str()));
  }
  if (plots.empty()) throw std::runtime_error("no cycle or failed run in any diagram to draw");
  job.render(script + plots + "\n", image);
}

}  // namespace wrc::cli::plot
