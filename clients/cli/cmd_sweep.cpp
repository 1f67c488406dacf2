// SPDX-License-Identifier: Apache-2.0
// wrc sweep: a grid of runs (any keys of the run parameter table, profiles, models, ...) run in
// processes of their own on this machine's cores, or as a Slurm job array, into one CSV with a
// row per run (cli/sweep/: the definition, the runs, the work directory, local and Slurm;
// cli/sweep/: the grid and the CSV).

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/output_paths.hpp"
#include "cli/plot/sweep_plot.hpp"
#include "cli/progress_bar.hpp"
#include "cli/sweep/sweep_definition.hpp"
#include "cli/sweep/sweep_local.hpp"
#include "cli/sweep/sweep_results.hpp"
#include "cli/sweep/sweep_slurm.hpp"
#include "cli/sweep/sweep_work.hpp"
#include "core/identity/geometry_key.hpp"

namespace wrc::cli {
namespace {

using RowMap = std::map<std::size_t, sweep::SweepRow>;

constexpr double kSlurmPollPeriod = 1.0;  // [s] between looks at the rows and at squeue

std::vector<OptionSpec> sweep_option_specs() {
  return {
      {"--extract", true,
       "what each row holds: groups final, maxima, counters, critical_speed, instances (who answered the "
       "queries over the bus, model/instance=queries) and paths of the run summary "
       "(run_quantities.y_over_q.left.t), comma-separated",
       "final,maxima,counters"},
      {"--critical-speeds", true, "speeds of the critical-speed scan FROM:TO:STEP [m/s]", "5:80:1"},
      {"--out", true, "the sweep's CSV; an existing one of the same sweep is resumed", "sweep.csv"},
      {"--work-dir", true, "the runs' rows, logs and Slurm scripts (shared by the nodes with --slurm)", "OUT.work"},
      {"--jobs", true, "runs at once on this machine", "the number of cores", NumberRange{1, 4096}},
      {"--retry-failed", false, "run the failed rows of a resumed sweep again", ""},
      {"--plot", true, "also draw --plot-y against --plot-x (.png or .svg)", "none"},
      {"--plot-x", true, "grid key along the plot's x", "the first grid key"},
      {"--plot-y", true, "result column of the plot", "the first result column"},
      {"--plot-by", true, "grid key with one line per value in the plot", "the second grid key, if any"},
      {"--slurm", false, "submit the runs as a Slurm job array (sbatch) and gather their rows", ""},
      {"--partition", true, "Slurm partition", "the cluster's default"},
      {"--time", true, "Slurm time limit per run (sbatch --time)", "the partition's default"},
      {"--array-limit", true, "most Slurm tasks running at once (--array=...%N)", "no limit", NumberRange{1, 1000000}},
      {"--sbatch-args", true, "further sbatch options, space-separated (e.g. '--account=A --qos=Q')", "none"},
      {"--no-wait", false, "with --slurm: submit and return; gather later with --gather", ""},
      {"--gather", false, "gather the rows the work directory holds into --out (after --slurm --no-wait)", ""},
      {"--bus", false,
       "run on the bus's services (start them first, e.g. wrc launch, on this or other machines): each run on a "
       "wrc-dynamicsd of its own, its contact queries spread over the READY instances of its model; the bus "
       "options (--lcm-url, --channel-prefix, --bus-key, --build-dir) go after --",
       "in-process"},
      {"--run-point", true, "run one grid point of --work-dir's sweep into its row (what each run process runs)", ""},
  };
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  for (char c : text + separator) {
    if (c == separator) {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part += c;
    }
  }
  return parts;
}

std::string point_text(const SweepDefinition& d, const sweep::Grid& grid, std::size_t point) {
  const auto values = grid.point(point);
  std::string text;
  for (std::size_t k = 0; k < values.size(); ++k) text += (k ? ", " : "") + d.axes[k].key + " = " + values[k];
  return text;
}

// The sweep's layout: every point's run parsed by `wrc run`'s options (a bad value is one line naming
// the point, before anything runs), every distinct geometry built once, the columns and units.
sweep::SweepLayout checked_layout(const SweepDefinition& d, bool check_every_point) {
  sweep::Grid grid;
  try {
    grid = sweep::Grid(d.axes);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  check_run_options(d.run_options, d.axes, d.bus);
  std::vector<std::string> units;
  for (const sweep::GridAxis& a : d.axes) units.push_back(grid_key_unit(a.key));
  protocol::RunRequest example;
  std::set<std::string> geometries;
  // What `wrc run` would print about a point's run (a lateral load set to 0 on a track), once per
  // distinct line with the number of points it applies to.
  std::vector<std::pair<std::string, std::size_t>> notes;
  const std::size_t checked = check_every_point ? grid.size() : 1;
  for (std::size_t p = 0; p < checked; ++p) {
    try {
      std::ostringstream note;
      const protocol::RunRequest request = sweep_run_request(run_arguments(d, grid.point(p)), "check", note, d.bus);
      if (!note.str().empty()) {
        auto same = std::find_if(notes.begin(), notes.end(), [&](const auto& n) { return n.first == note.str(); });
        if (same == notes.end())
          notes.emplace_back(note.str(), 1);
        else
          ++same->second;
      }
      // Built once per distinct geometry (its options as wrc-contactd would get them).
      std::string key;
      for (const std::string& a : geometry_arguments(request.geometry)) key += a + '\n';
      if (geometries.insert(key).second) make_geometry(request.geometry);
      if (p == 0) example = request;
    } catch (const std::exception& e) {
      throw UsageError("grid point " + std::to_string(p) + " (" + point_text(d, grid, p) + "): " + e.what());
    }
  }
  for (const auto& [line, points] : notes)
    std::cerr << "sweep: "
              << (!check_every_point ? "grid point 0"
                  : points == checked ? "every run"
                                      : std::to_string(points) + " of " + std::to_string(checked) + " runs")
              << ": " << line;
  std::vector<std::string> names;
  const std::vector<ResultColumn> columns = result_columns(d.extract, example);
  bool critical = false;
  for (const ResultColumn& c : columns) {
    names.push_back(c.name());
    critical = critical || c.path == "critical_speed";
  }
  if (critical) critical_speed_scan(d.critical_speeds);
  return sweep::SweepLayout(grid, units, names);
}

std::vector<ResultColumn> columns_of(const SweepDefinition& d, const sweep::Grid& grid) {
  std::ostringstream unused;  // checked_layout has said it
  return result_columns(d.extract, sweep_run_request(run_arguments(d, grid.point(0)), "check", unused, d.bus));
}

// `wrc sweep --run-point I --work-dir DIR`: one run into its row file.
int run_one_point(const Options& o) {
  const SweepWork work(o.required_text("--work-dir"));
  const SweepDefinition d = work.definition();
  const sweep::Grid grid(d.axes);
  const long point = std::stol(o.required_text("--run-point"));
  if (point < 0 || static_cast<std::size_t>(point) >= grid.size())
    throw UsageError("--run-point " + o.text("--run-point") + ": the grid has points 0 to " + std::to_string(grid.size() - 1));
  const std::size_t p = static_cast<std::size_t>(point);
  std::cerr << "sweep point " << p << ": " << point_text(d, grid, p) << "\n";
  const sweep::SweepRow row = run_sweep_point(d, columns_of(d, grid), p, grid.point(p));
  work.write_row(row, grid);
  std::cerr << "sweep point " << p << ": " << row.status << (row.error.empty() ? "" : " (" + row.error + ")") << " in "
            << row.wall_time << " s\n";
  return 0;
}

void report(const RowMap& rows, std::size_t total, const std::string& out, double wall) {
  std::size_t failed = 0;
  for (const auto& [p, r] : rows) failed += r.status != "finished";
  std::cerr << "sweep: " << rows.size() << " of " << total << " runs in " << out << " (" << rows.size() - failed
            << " finished, " << failed << " failed), " << wall << " s wall\n";
  std::size_t shown = 0;
  for (const auto& [p, r] : rows)
    if (r.status != "finished" && shown++ < 5) std::cerr << "  point " << p << " " << r.status << ": " << r.error << "\n";
}

void draw(const Options& o, const sweep::SweepLayout& layout, const std::string& out) {
  if (!o.has("--plot")) return;
  const sweep::CsvTable table = sweep::read_csv_file(out);
  const std::size_t keys = layout.grid().axes().size();
  const std::size_t x = plot::sweep_column(table, o.text("--plot-x", table.header[1]), "--plot-x");
  const std::size_t y = plot::sweep_column(table, o.text("--plot-y", table.header[keys + 2]), "--plot-y");
  const std::size_t by = o.has("--plot-by") ? plot::sweep_column(table, o.text("--plot-by"), "--plot-by")
                         : keys >= 2 && x != 2 ? 2 : keys >= 2 ? 1 : table.header.size();
  draw_sweep(table, x, y, by, plot::image_request(o.text("--plot"), 1200, 800), "wrc sweep: " + out);
  std::cerr << "sweep: wrote " << o.text("--plot") << "\n";
}

// The command line of a sweep: --grid may come many times and everything after `--` is the runs'
// own, so both are taken out before the options are read.
struct SweepArguments {
  std::vector<std::string> options;      // the sweep's own, --grid taken out
  std::vector<std::string> run_options;  // after `--`
  std::vector<sweep::GridAxis> axes;     // one per --grid
};

SweepArguments split_sweep_arguments(const std::vector<std::string>& all_args) {
  SweepArguments out;
  for (std::size_t i = 0; i < all_args.size(); ++i) {
    const std::string& a = all_args[i];
    if (a == "--") {
      out.run_options.assign(all_args.begin() + static_cast<long>(i) + 1, all_args.end());
      break;
    }
    std::string grid;
    if (a == "--grid") {
      if (i + 1 >= all_args.size()) throw UsageError("--grid needs KEY=VALUES");
      grid = all_args[++i];
    } else if (a.rfind("--grid=", 0) == 0) {
      grid = a.substr(7);
    } else {
      out.options.push_back(a);
      continue;
    }
    try {
      out.axes.push_back(sweep::parse_grid_axis(grid));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--") + e.what());
    }
  }
  return out;
}

void print_sweep_help(const Options& o) {
  std::cout << o.help()
            << "\nRuns `wrc run` at every point of the grid (the first key varies slowest), each in a process of its\n"
               "own with the contact model in-process, and writes one CSV row per run in grid order: point, the\n"
               "keys, status, what --extract names, error, wall_time. Keys: any run parameter (speed, friction, y0,\n"
               "...), the profile and track options (wheel, rail, gauge, inclination, r0, ...), model, suspension,\n"
               "params, track, irregularities, swap_at. A failed run is a row with its error. Run again with the\n"
               "same --out to resume: rows already there are kept. --slurm submits the runs as a job array instead.\n"
               "`wrc sweep --compare A.csv B.csv` compares two sweep CSVs, every column but wall_time [s].\n"
               "Example: wrc sweep --grid speed=10:40:10 --grid friction=0.2,0.3 -- --model onepoint --t-end 1\n"
               "docs/sweep.md.\n";
}

// The rows already done: those in the CSV at out and those gathered from the work directory,
// without the failed ones under --retry-failed (forgotten in the work directory too).
RowMap rows_already_done(const Options& o, const std::string& out, const sweep::SweepLayout& layout,
                         const SweepWork& work, std::size_t& in_csv, std::size_t& gathered) {
  RowMap rows;
  if (std::filesystem::exists(out)) {
    try {
      rows = layout.rows_of(sweep::read_csv_file(out), out);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  in_csv = rows.size();
  gathered = work.gather(layout, rows);
  if (o.has("--retry-failed")) {
    for (auto it = rows.begin(); it != rows.end();) {
      if (it->second.status != "finished") {
        work.forget(it->first);
        it = rows.erase(it);
      } else {
        ++it;
      }
    }
  }
  return rows;
}

// The pending points as a Slurm job array, waited for (unless --no-wait) while their rows are
// gathered; a point whose task ended without a result becomes a failed row naming its log.
// Returns false when the command ends without waiting.
bool run_on_slurm(const Options& o, const SweepWork& work, const sweep::SweepLayout& layout,
                  const std::vector<std::size_t>& pending, RowMap& rows, const std::function<void()>& write) {
  SlurmSubmission s;
  s.partition = o.text("--partition");
  s.time = o.text("--time");
  s.sbatch_args = split(o.text("--sbatch-args"), ' ');
  s.array_limit = o.has("--array-limit") ? o.integer("--array-limit") : 0;
  const std::string job = submit_to_slurm(work, pending, s);
  std::cerr << "sweep: Slurm job " << job << ", an array of " << pending.size() << " tasks (script and list in "
            << work.slurm_directory() << ")\n";
  if (o.has("--no-wait")) {
    std::cerr << "sweep: gather its rows with the same command and --gather (or run it again to resume)\n";
    return false;
  }
  ProgressBar bar("sweep (Slurm job " + job + ")");
  const std::set<std::size_t> submitted(pending.begin(), pending.end());
  auto done = [&] {
    std::size_t n = 0, failed = 0;
    for (std::size_t p : submitted)
      if (rows.count(p)) {
        ++n;
        failed += rows[p].status != "finished";
      }
    return std::make_pair(n, failed);
  };
  bool active = true;
  while (active) {
    std::this_thread::sleep_for(std::chrono::duration<double>(kSlurmPollPeriod));
    active = slurm_job_active(job);
    if (work.gather(layout, rows) > 0) write();
    const auto [n, failed] = done();
    bar.update(static_cast<long>(n), static_cast<long>(submitted.size()),
               std::to_string(n) + "/" + std::to_string(submitted.size()) + " runs, " + std::to_string(failed) + " failed");
  }
  bar.finish();
  for (std::size_t p : submitted) {
    if (rows.count(p)) continue;
    sweep::SweepRow row;
    row.point = p;
    row.status = "failed";
    row.results.assign(layout.result_count(), "");
    row.error = "the Slurm task of this point (job " + job + ") ended without a result; its log: " +
                work.logs_directory() + "/slurm-" + job + "_<task>.log";
    rows[p] = row;
  }
  write();
  return true;
}

int run_sweep(const std::vector<std::string>& all_args) {
  const SweepArguments arguments = split_sweep_arguments(all_args);
  std::vector<OptionSpec> specs = sweep_option_specs();
  specs.insert(specs.begin(), {"--grid", true, "KEY=VALUES, repeated per key: a list 0.2,0.3, a range FROM:TO:STEP, or both", ""});
  const Options o("sweep", "--grid KEY=VALUES [--grid ...] [options] -- [wrc run options for every run]", specs,
                  arguments.options);
  if (o.help_requested()) {
    print_sweep_help(o);
    return 0;
  }
  if (o.has("--run-point")) return run_one_point(o);

  const std::string out = o.text("--out", "sweep.csv");
  const SweepWork work(o.text("--work-dir", out + ".work"));
  SweepDefinition d;
  if (o.has("--gather") && arguments.axes.empty()) {
    d = work.definition();
  } else {
    d.axes = arguments.axes;
    d.run_options = arguments.run_options;
    d.extract = split(o.text("--extract", "final,maxima,counters"), ',');
    d.critical_speeds = o.text("--critical-speeds", "5:80:1");
    d.bus = o.has("--bus");
  }
  const sweep::SweepLayout layout = checked_layout(d, !o.has("--gather"));
  check_output_path(out, "--out");
  if (o.has("--plot")) plot::image_request(o.text("--plot"), 1200, 800);
  work.prepare(d);

  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::size_t in_csv = 0, gathered = 0;
  RowMap rows = rows_already_done(o, out, layout, work, in_csv, gathered);
  const std::function<void()> write = [&] { sweep::write_csv_file(out, layout.table(rows)); };
  write();
  std::vector<std::size_t> pending;
  for (std::size_t p = 0; p < layout.grid().size(); ++p)
    if (!rows.count(p)) pending.push_back(p);
  std::cerr << "sweep: " << layout.grid().size() << " runs";
  if (in_csv + gathered > 0)
    std::cerr << ", " << rows.size() << " already done (" << in_csv << " in " << out << ", " << gathered
              << " more in " << work.directory() << ")";
  std::cerr << ", " << pending.size() << " to run\n";

  if (o.has("--gather")) {
    report(rows, layout.grid().size(), out, elapsed());
    draw(o, layout, out);
    return pending.empty() ? 0 : 1;
  }
  bool complete = true;
  if (pending.empty()) {
  } else if (!o.has("--slurm")) {
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int jobs = o.has("--jobs") ? o.integer("--jobs") : cores;
    std::cerr << "sweep: " << std::min<std::size_t>(static_cast<std::size_t>(jobs), pending.size())
              << " at once on this machine (" << cores << " cores)\n";
    complete = run_points_locally(work, layout, pending, jobs, [&](const sweep::SweepRow& row) {
      rows[row.point] = row;
      write();
    });
  } else if (!run_on_slurm(o, work, layout, pending, rows, write)) {
    return 0;
  }
  report(rows, layout.grid().size(), out, elapsed());
  if (!complete) {
    std::cerr << "sweep: run the same command again to resume\n";
    return 130;
  }
  draw(o, layout, out);
  return 0;
}

// `wrc sweep --compare A.csv B.csv`: the same rows, every column but the wall time.
int compare(const std::vector<std::string>& args) {
  if (args.size() != 3) throw UsageError("sweep --compare A.csv B.csv");
  const sweep::CsvTable a = sweep::read_csv_file(args[1]);
  const sweep::CsvTable b = sweep::read_csv_file(args[2]);
  const std::vector<std::string> differences = sweep::compare_sweep_tables(a, b);
  if (differences.empty()) {
    std::cout << "same: " << a.rows.size() << " rows, " << a.header.size() - 1 << " columns compared ("
              << sweep::kWallTimeColumn << " left out)\n";
    return 0;
  }
  for (const std::string& d : differences) std::cout << d << "\n";
  return 1;
}

int sweep_command(const std::vector<std::string>& args) {
  if (!args.empty() && args[0] == "--compare") return compare(args);
  return run_sweep(args);
}

const CommandRegistrar registrar{
    {"sweep", "a grid of runs on this machine's cores or a Slurm cluster, one CSV row per run (docs/sweep.md)",
     sweep_command}};

}  // namespace
}  // namespace wrc::cli
