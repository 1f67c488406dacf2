// SPDX-License-Identifier: Apache-2.0
// wrc plot sweep FILE.csv: a result of a sweep (wrc sweep) against a grid key, one line per value
// of another key.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <map>

#include "cli/options.hpp"
#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/plot/sweep_plot.hpp"

namespace wrc::cli::plot {
namespace {

bool is_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(value);
}

std::string without_unit(const std::string& header) { return header.substr(0, header.find(" [")); }

int run_sweep_plot(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs{
      {"--x", true, "grid key (or column) along x", "the first grid key"},
      {"--y", true, "result column along y, e.g. final_state.y or run_quantities.y_over_q.left.max", ""},
      {"--by", true, "grid key with one line per value", "none"},
  };
  for (const auto& spec : image_option_specs("sweep.png")) specs.push_back(spec);
  const Options o("plot sweep", "FILE.csv --y COLUMN [--x KEY] [--by KEY] [--out FILE]", specs, args,
                  Positional::kAllowed);
  if (o.help_requested()) {
    std::cout << o.help() << "\nDraws a result of a sweep's CSV (wrc sweep) against a grid key; failed runs are left out.\n";
    return 0;
  }
  if (o.positional().size() != 1) throw UsageError("plot sweep: give one sweep CSV file");
  const std::string file = o.positional().front();
  sweep::CsvTable table;
  try {
    table = sweep::read_csv_file(file);
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  if (table.header.size() < 2 || table.header[0] != "point [-]")
    throw UsageError(file + ": not a sweep's CSV (its first column is not point [-])");
  const std::size_t x = sweep_column(table, o.text("--x", table.header[1]), "--x");
  const std::size_t y = sweep_column(table, o.required_text("--y"), "--y");
  const std::size_t by = o.has("--by") ? sweep_column(table, o.text("--by"), "--by") : table.header.size();
  const ImageRequest image = image_from_options(o, "sweep.png");
  draw_sweep(table, x, y, by, image, "wrc sweep: " + file);
  return report_written(image);
}

const PlotKindRegistrar registrar{{"sweep", "a result of a sweep's CSV against a grid key (wrc sweep)", run_sweep_plot, 60}};

}  // namespace

std::size_t sweep_column(const sweep::CsvTable& table, const std::string& name, const std::string& what) {
  for (std::size_t i = 0; i < table.header.size(); ++i)
    if (table.header[i] == name || without_unit(table.header[i]) == name) return i;
  std::string names;
  for (const std::string& h : table.header) names += (names.empty() ? "" : ", ") + without_unit(h);
  throw UsageError(what + " " + name + ": no such column (the columns: " + names + ")");
}

void draw_sweep(const sweep::CsvTable& table, std::size_t x, std::size_t y, std::size_t by, const ImageRequest& image,
                const std::string& title) {
  const std::size_t status = static_cast<std::size_t>(
      std::find(table.header.begin(), table.header.end(), "status [-]") - table.header.begin());
  // x: numbers, or categories in the order of the rows (the grid's order).
  bool numeric_x = true;
  std::vector<std::string> categories;
  for (const auto& row : table.rows) {
    double v;
    if (!is_number(row[x], v)) numeric_x = false;
    if (std::find(categories.begin(), categories.end(), row[x]) == categories.end()) categories.push_back(row[x]);
  }
  std::vector<std::string> groups;  // values of by, in row order
  std::map<std::string, std::vector<std::pair<double, double>>> lines;
  std::size_t points = 0;
  for (const auto& row : table.rows) {
    double v = 0;
    if (status < row.size() && row[status] != "finished") continue;
    if (!is_number(row[y], v)) continue;
    const std::string group = by < row.size() ? row[by] : "";
    if (!lines.count(group)) groups.push_back(group);
    double xv = 0;
    if (numeric_x)
      is_number(row[x], xv);
    else
      xv = static_cast<double>(std::find(categories.begin(), categories.end(), row[x]) - categories.begin());
    lines[group].push_back({xv, v});
    ++points;
  }
  if (points == 0) throw std::runtime_error("plot sweep: no finished run has a value of " + table.header[y]);
  GnuplotJob job;
  std::string plots;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::string data = "line" + std::to_string(g) + ".dat";
    {
      auto out = job.open_data(data);
      auto& pts = lines[groups[g]];
      std::sort(pts.begin(), pts.end());
      for (const auto& [a, b] : pts) out << a << " " << b << "\n";
    }
    const std::string name = by < table.header.size() ? without_unit(table.header[by]) + " = " + groups[g] : without_unit(table.header[y]);
    plots += std::string(plots.empty() ? "plot " : ", ") + quoted(job.data_path(data)) +
             " using 1:2 with linespoints pt 7 ps 0.7 lw 1.5 title " + quoted(name);
  }
  std::string script = "set title " + quoted(title) + " noenhanced\nset grid\nset key outside right noenhanced\n";
  script += "set xlabel " + quoted(table.header[x]) + " noenhanced\nset ylabel " + quoted(table.header[y]) + " noenhanced\n";
  if (!numeric_x) {
    script += "set xtics (";
    for (std::size_t i = 0; i < categories.size(); ++i)
      script += (i ? ", " : "") + quoted(categories[i]) + " " + std::to_string(i);
    script += ") noenhanced\nset xrange [-0.5:" + std::to_string(categories.size()) + "-0.5]\n";
  }
  job.render(script + plots + "\n", image);
}

}  // namespace wrc::cli::plot
