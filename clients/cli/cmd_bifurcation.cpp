// SPDX-License-Identifier: Apache-2.0
// wrc bifurcation: the hunting bifurcation diagram of the wheelset, or with --vehicle FILE of
// several bodies the vehicle's (core/vehicle_dynamics/vehicle_hunting_run.hpp, docs/vehicle.md), on
// straight track by time simulation (core/dynamics/hunting_continuation.hpp, docs/bifurcation.md),
// in-process with the chosen contact model: the centred branch from a small disturbance, the stable limit-cycle branch
// by ramp-down continuation, the nonlinear critical speed by bisection, the linear critical speed
// (core/dynamics/linear_stability.hpp) for comparison, a CSV of every run and the diagram.

#include <chrono>
#include <cstdio>
#include <iostream>
#include <functional>
#include <memory>
#include <optional>

#include "cli/centred_run_options.hpp"
#include "cli/run_options.hpp"
#include "cli/command.hpp"
#include "options/fit_options.hpp"
#include "cli/in_process_contact.hpp"
#include "cli/options.hpp"
#include "cli/output_paths.hpp"
#include "cli/plot/bifurcation_plot.hpp"
#include "cli/plot/gnuplot_job.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"
#include "cli/speed_scan_option.hpp"
#include "core/dynamics/hunting_continuation.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/numerics/number_text.hpp"
#include "core/vehicle_dynamics/vehicle_hunting_run.hpp"
#include "cli/vehicle_stability.hpp"
#include "cli/sweep/sweep_table.hpp"
#include "options/parameter_options.hpp"

namespace wrc::cli {
namespace {

// The integrator settings a hunting run takes from the command line (t_end and the output period
// are the run's own).
bool is_integrator_option(const std::string& key) {
  return key == "rtol" || key == "position_tolerance" || key == "velocity_tolerance" || key == "max_step";
}

std::vector<std::string> csv_row(const std::string& branch, const HuntingRun& r, double wall) {
  return {branch,
          number_text(r.speed),
          hunting_state_name(r.state),
          number_text(r.amplitude()),
          number_text(r.cycle.mean),
          number_text(r.yaw_amplitude),
          number_text(r.cycle.frequency()),
          number_text(r.cycle.growth),
          number_text(r.largest_contact_angle),
          r.flange_contact ? "1" : "0",
          number_text(r.start.y),
          number_text(r.simulated_time),
          number_text(wall),
          r.message};
}

std::vector<OptionSpec> bifurcation_option_specs() {
  const ContinuationSettings defaults;
  std::vector<OptionSpec> specs{
      {"--model", true, "contact model: onepoint, interp, multipoint or spline", ""},
      {"--speeds", true, "speeds FROM:TO:STEP [m/s]; the ramp-down starts at the highest", "30:90:5"},
      {"--disturbance", true, "y0 of the centred branch's runs [m]", number_text(defaults.small_disturbance.y),
          kLateralShiftRange},
      {"--start-amplitude", true, "y0 of the ramp-down's first run, at the highest speed [m]",
       number_text(defaults.large_disturbance.y), kLateralShiftRange},
      {"--settle-time", true, "simulated time before a run is first judged [s]", number_text(defaults.run.settle_time),
          NumberRange{1e-3, 1e4}},
      {"--window", true, "the cycles are measured over the last window [s]", number_text(defaults.run.window),
          NumberRange{1e-3, 1e4}},
      {"--max-time", true, "longest run [s]", number_text(defaults.run.max_time), NumberRange{1e-3, 1e4}},
      {"--growth-tolerance", true, "|growth - 1| per cycle of a converged cycle [-]",
       number_text(defaults.run.growth_tolerance), NumberRange{1e-6, 0.5}},
      {"--centred-amplitude", true, "amplitude below which the wheelset is centred [m]",
       number_text(defaults.run.centred_amplitude), NumberRange{1e-12, 0.05}},
      {"--speed-tolerance", true, "bracket of the nonlinear critical speed at the end [m/s]",
       number_text(defaults.speed_tolerance), NumberRange{1e-6, 1e3}},
      {"--persisting-amplitude", true, "a cycle persists only with at least this amplitude [m] (0: any)",
       number_text(defaults.persisting_amplitude), NumberRange{0, 0.05}},
      {"--unstable", false, "estimate the unstable cycle where the centred state and a cycle are both stable "
       "(bisection on y0, 6 runs of 2 s per speed)", ""},
      {"--out", true, "every run (CSV, units in the header)", "bifurcation.csv"},
      {"--plot", true, "the bifurcation diagram (.png or .svg)", "bifurcation.png"},
  };
  const std::vector<OptionSpec> sources = wheelset_source_option_specs();
  specs.insert(specs.begin() + 2, sources.begin(), sources.end());
  for (auto& spec : parameter_option_specs(wheelset_parameter_table(), WheelsetParameters{})) specs.push_back(spec);
  for (const auto& p : integrator_settings_table())
    if (is_integrator_option(p.key)) specs.push_back(parameter_option_spec(p, p.get(IntegratorSettings{})));
  for (auto& spec : profile_option_specs()) specs.push_back(spec);
  for (auto& spec : spline_model_fit_option_specs()) specs.push_back(spec);
  return specs;
}

// The continuation's settings from the command line, validated.
ContinuationSettings continuation_settings_from(const Options& o) {
  ContinuationSettings settings;
  settings.small_disturbance.y = o.number("--disturbance");
  settings.large_disturbance.y = o.number("--start-amplitude");
  settings.run.settle_time = o.number("--settle-time");
  settings.run.window = o.number("--window");
  settings.run.max_time = o.number("--max-time");
  settings.run.growth_tolerance = o.number("--growth-tolerance");
  settings.run.centred_amplitude = o.number("--centred-amplitude");
  settings.speed_tolerance = o.number("--speed-tolerance");
  settings.persisting_amplitude = o.number("--persisting-amplitude");
  try {
    settings.validate();
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return settings;
}

void print_table_header() {
  std::printf("%-11s %8s %-12s %11s %12s %9s %8s %10s %8s %7s\n", "branch", "V [m/s]", "state", "ampl. [mm]",
              "yaw [mrad]", "freq [Hz]", "growth", "angle [deg]", "t [s]", "wall [s]");
}

// One line of the table for run r of a branch (wall [s]), and what follows it (a message, or the
// unstable cycle's bracket).
void print_run_row(const char* branch, const char* state, const HuntingRun& r, double wall, const std::string& tail) {
  std::printf("%-11s %8.3f %-12s %11.4f %12.4f %9.4f %8.4f %10.2f %8.2f %7.1f%s%s\n", branch, r.speed, state,
              r.amplitude() * 1e3, r.yaw_amplitude * 1e3, r.cycle.frequency(), r.cycle.growth,
              r.largest_contact_angle * 180 / M_PI, r.simulated_time, wall, tail.empty() ? "" : "  ", tail.c_str());
  std::fflush(stdout);
}

// Where the small start decayed and the ramp-down's cycle persisted, both are stable: an unstable
// cycle separates them, estimated by bisection on y0 with short runs; a row per such speed.
void add_unstable_cycles(const HuntingDiagram& d, const std::function<HuntingRunner(const HuntingSettings&)>& runner,
                         const ContinuationSettings& settings, sweep::CsvTable& table) {
  HuntingSettings short_runs = settings.run;
  short_runs.settle_time = short_runs.window = short_runs.max_time = 2.0;
  short_runs.centred_amplitude = 1e-9;
  const HuntingRunner probe = runner(short_runs);
  for (const HuntingRun& cycle : d.ramp_down) {
    if (!cycle.persists()) continue;
    bool decayed = false;
    for (const HuntingRun& c : d.centred)
      if (c.speed == cycle.speed) decayed = c.state == HuntingState::kCentred || c.state == HuntingState::kDecaying;
    if (!decayed) continue;
    const auto start = std::chrono::steady_clock::now();
    const UnstableCycle u = unstable_cycle(probe, cycle.speed, settings.small_disturbance.y, cycle.amplitude(), 6);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    HuntingRun row = u.run;
    row.speed = cycle.speed;
    row.start.y = 0.5 * (u.decaying_start + u.growing_start);
    // The estimate drawn: the separating start amplitude (the 2 s run from just below it has
    // decayed by its end, so its own amplitude says less).
    row.cycle.amplitude = row.start.y;
    char bracket[96];
    std::snprintf(bracket, sizeof bracket, "y0 between %.4f and %.4f mm", u.decaying_start * 1e3,
                  u.growing_start * 1e3);
    print_run_row("unstable", "separatrix", row, wall, bracket);
    table.rows.push_back(csv_row("unstable", row, wall));
  }
}

// The linear critical speed: printed, and a marker row when found.
void report_linear_critical_speed(const CriticalSpeed& linear, const std::vector<double>& speeds,
                                  sweep::CsvTable& table) {
  if (!linear.found) {
    std::printf("linear critical speed: none in %g..%g m/s\n", speeds.front(), speeds.back());
    return;
  }
  std::printf("linear critical speed: %.3f m/s (%.1f km/h), %.4f Hz\n", linear.speed, linear.speed * 3.6,
              linear.frequency);
  HuntingRun marker;
  marker.speed = linear.speed;
  marker.cycle.period = linear.frequency > 0 ? 1.0 / linear.frequency : 0;
  marker.state = HuntingState::kCentred;
  table.rows.push_back(csv_row("linear-critical", marker, 0));
}

// The nonlinear critical speed, or why there is none: printed, and its row when found.
void report_nonlinear_critical_speed(const HuntingDiagram& d, const std::vector<double>& speeds,
                                     const ContinuationSettings& settings, sweep::CsvTable& table) {
  if (d.critical.found) {
    std::printf("nonlinear critical speed: %.3f m/s (%.1f km/h): the lowest speed with a persisting cycle "
                "(collapsed at %.3f m/s); its amplitude %.3f mm, %.4f Hz\n",
                d.critical.speed, d.critical.speed * 3.6, d.critical.collapsed_at, d.critical.cycle.amplitude() * 1e3,
                d.critical.cycle.cycle.frequency());
    table.rows.push_back(csv_row("nonlinear-critical", d.critical.cycle, 0));
  } else if (!d.ramp_down.empty() && d.ramp_down.back().state == HuntingState::kFailed) {
    std::printf("nonlinear critical speed: not found, the ramp-down failed at %.3f m/s: %s\n",
                d.ramp_down.back().speed, d.ramp_down.back().message.c_str());
  } else if (!d.ramp_down.empty() && d.ramp_down.back().persists() &&
             d.ramp_down.back().amplitude() >= settings.persisting_amplitude) {
    std::printf("nonlinear critical speed: below %g m/s (the cycle persisted down to the lowest speed)\n",
                speeds.front());
  } else {
    std::printf("nonlinear critical speed: none: no persisting cycle at %g m/s from y0 = %g m\n", speeds.back(),
                settings.large_disturbance.y);
  }
}

int run_bifurcation(const std::vector<std::string>& args) {
  const Options o("bifurcation", "--model M [--speeds 30:90:5] [--out FILE.csv] [--plot FILE.png] [options]",
                  bifurcation_option_specs(), args);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nThe hunting bifurcation diagram by time simulation on straight track (contact model M,\n"
                 "in-process): at every speed a run from a small disturbance (the centred branch); from the\n"
                 "highest speed down, runs each started from the previous run's final state (the stable\n"
                 "limit-cycle branch) until the cycle collapses; the nonlinear critical speed (the lowest speed\n"
                 "with a persisting cycle) by bisection; the linear critical speed for comparison. Every run goes\n"
                 "until its oscillation has settled (constant amplitude; irregular: cycles that differ under an\n"
                 "envelope that holds; or centred) or --max-time. The lateral load is set to 0.\n"
                 "docs/bifurcation.md.\n"
                 "With --vehicle FILE of several bodies: the vehicle's diagram, each run judged by its first\n"
                 "wheelset; a fresh run holds that wheelset at y0 with the vehicle at rest about it, the\n"
                 "ramp-down continues the whole vehicle's state. docs/vehicle.md.\n";
    return 0;
  }
  const std::string model = o.choice("--model", contact_model_names());
  if (model.empty()) throw UsageError("--model is required (onepoint, interp, multipoint or spline)");
  RunSpec spec;
  std::optional<VehicleDescription> vehicle;  // a vehicle of several bodies
  apply_wheelset_sources(o, spec, std::cout, &vehicle);
  apply_parameter_options(wheelset_parameter_table(), o, spec.wheelset);
  if (!vehicle) zero_lateral_load_unless_given(o, spec.wheelset, "hunting about the centred state on straight track", std::cout);
  for (const auto& p : integrator_settings_table())
    if (is_integrator_option(p.key) && o.has(p.option_name()))
      p.set(spec.integrator, parameter_option_value(p, o.text(p.option_name())));
  const std::vector<double> speeds = parse_speed_scan(o.text("--speeds", "30:90:5"), "--speeds");
  if (speeds.size() < 2) throw UsageError("--speeds: give at least 2 speeds");
  const ContinuationSettings settings = continuation_settings_from(o);
  const std::string csv = o.text("--out", "bifurcation.csv");
  const std::string picture = o.text("--plot", "bifurcation.png");
  check_output_path(csv, "--out");
  plot::image_request(picture, 1200, 800);  // checks the extension and the path before the work

  const GeometrySpec geometry_spec = geometry_spec_from_options(o);
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(geometry_spec));
  const double r0 = geometry_spec.track.nominal_radius;
  if (contact_model_entry(model).needs_data)
    std::cerr << "fitting the spline model (in-process, as wrc run --in-process does) ...\n";
  const auto contact = in_process_contact(model, geometry, fit_options_from(o));

  // The runs' runner, and the linear critical speed over the same speeds (docs/stability.md).
  const CriticalSpeed linear = linear_critical_speed(spec, vehicle, contact, r0, speeds);
  std::function<HuntingRunner(const HuntingSettings&)> runner_with;
  std::string subject = "the wheelset";
  if (vehicle) {
    const VehicleRunSpec vehicle_spec{*vehicle, spec, std::nullopt};
    runner_with = [vehicle_spec, contact, r0](const HuntingSettings& s) {
      return vehicle_hunting_runner(vehicle_spec, contact, r0, s);
    };
    subject = vehicle->name + ", judged by its first wheelset";
  } else {
    runner_with = [spec, contact, r0](const HuntingSettings& s) { return hunting_runner(spec, contact, r0, s); };
  }

  std::printf("hunting bifurcation of %s, %s contact, %s\n", subject.c_str(), model.c_str(),
              plot::geometry_title(geometry_spec).c_str());
  print_table_header();
  sweep::CsvTable table;
  table.header = plot::bifurcation_csv_header();
  auto last = std::chrono::steady_clock::now();
  const HuntingRunner runner = runner_with(settings.run);
  const HuntingDiagram d = trace_hunting(speeds, runner, settings, [&](const char* branch, const HuntingRun& r) {
    const auto now = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    last = now;
    print_run_row(branch, hunting_state_name(r.state), r, wall, r.message);
    table.rows.push_back(csv_row(branch, r, wall));
  });
  if (o.has("--unstable")) add_unstable_cycles(d, runner_with, settings, table);
  report_linear_critical_speed(linear, speeds, table);
  report_nonlinear_critical_speed(d, speeds, settings, table);
  sweep::write_csv_file(csv, table);
  std::cout << "wrote " << csv << "\n";
  plot::draw_bifurcation(table, plot::image_request(picture, 1200, 800),
                         "wrc bifurcation: " + (vehicle ? vehicle->name + ", " : std::string()) + model + " contact, " +
                             plot::geometry_title(geometry_spec));
  std::cout << "wrote " << picture << "\n";
  return 0;
}

const CommandRegistrar registrar{
    {"bifurcation", "hunting bifurcation diagram by simulation: limit cycles, nonlinear critical speed, plot",
     run_bifurcation}};

}  // namespace
}  // namespace wrc::cli
