// wrc run: one wheelset run on wrc-dynamicsd (started, with the contact services it needs, when
// none runs), with a progress bar, the state history as CSV and the summary as JSON.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bus/auth/signed_publish.hpp"
#include "bus/process/build_paths.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "cli/progress_bar.hpp"
#include "cli/service_starter.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/models/contact_model_factory.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/run_status_t.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/wheelset_state_t.hpp"

namespace wrc::cli {
namespace {

constexpr double kCommandRepeat = 0.5;    // [s] re-send the START until the dynamics acknowledges it
constexpr double kSilenceLimit = 30.0;    // [s] without any status of the run: the dynamics is gone

std::vector<protocol::ScheduledSwap> parse_swaps(const std::string& text, double t_end) {
  std::vector<protocol::ScheduledSwap> swaps;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) throw UsageError("--swap-at: '" + item + "' is not T:MODEL");
    protocol::ScheduledSwap s;
    s.t = parse_finite(item.substr(0, colon), "--swap-at");
    s.model = item.substr(colon + 1);
    contact_model_entry(s.model);
    if (!(s.t > (swaps.empty() ? 0.0 : swaps.back().t) && s.t < t_end))
      throw UsageError("--swap-at: times must increase within (0, t_end): '" + item + "'");
    swaps.push_back(s);
  }
  return swaps;
}

nlohmann::json summary_json(const run_summary_t& s, const protocol::RunRequest& request, const std::string& key) {
  nlohmann::json j;
  j["run_id"] = s.run_id;
  j["state"] = protocol::run_state_name(s.state);
  j["message"] = s.message;
  j["model"] = s.model;
  j["initial_model"] = request.model;
  j["formulation"] = s.formulation;
  j["in_process"] = request.in_process;
  j["geometry_key"] = key;
  j["t_end"] = s.t_end;
  j["final_state"] = {{"y", s.y},
                      {"z", s.z},
                      {"roll", s.roll},
                      {"yaw", s.yaw},
                      {"y_dot", s.y_dot},
                      {"z_dot", s.z_dot},
                      {"roll_dot", s.roll_dot},
                      {"yaw_dot", s.yaw_dot},
                      {"spin_rate", s.spin_rate},
                      {"normal_force_left", s.normal_force[0]},
                      {"normal_force_right", s.normal_force[1]},
                      {"s_wheel_left", s.s_wheel[0]},
                      {"s_wheel_right", s.s_wheel[1]}};
  const integrator_stats_t& c = s.stats;
  j["wall_time"] = s.wall_time;
  j["counters"] = {{"steps", c.steps},
                   {"residual_evals", c.rhs_evals},
                   {"jacobian_residual_evals", c.rhs_evals_jac},
                   {"jacobian_evals", c.jac_evals},
                   {"lin_setups", c.lin_setups},
                   {"err_test_fails", c.err_test_fails},
                   {"nonlin_iters", c.nonlin_iters},
                   {"nonlin_conv_fails", c.nonlin_conv_fails},
                   {"root_evals", c.root_evals},
                   {"root_returns", c.root_returns},
                   {"restarts", c.restarts},
                   {"contact_switches", c.contact_switches},
                   {"contact_queries", c.contact_queries},
                   {"contact_configurations", c.contact_configurations},
                   {"contact_retries", c.contact_retries},
                   {"contact_timeouts", c.contact_timeouts},
                   {"missed_switches", c.missed_switches},
                   {"two_point_entries", c.two_point_entries},
                   {"two_point_time", c.two_point_time},
                   {"max_branch_excess", c.max_branch_excess},
                   {"floored_patches", c.floored_patches},
                   {"floored_time", c.floored_time},
                   {"last_order", c.last_order},
                   {"last_step", c.last_step}};
  nlohmann::json swaps = nlohmann::json::array();
  for (std::size_t k = 0; k < s.swap_times.size(); ++k)
    swaps.push_back({{"t", s.swap_times[k]}, {"model", s.swap_models[k]}});
  j["swaps"] = swaps;
  nlohmann::json parameters;
  for (const RunParameter& p : run_parameter_table()) {
    if (p.kind == RunParameterKind::kBoolean)
      parameters[p.key] = p.get(request.spec) != 0.0;
    else
      parameters[p.key] = p.get(request.spec);
  }
  j["parameters"] = parameters;
  return j;
}

void write_history(const std::string& path, const std::map<double, wheelset_state_t>& history) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write the history");
  out << "t,y,z,roll,yaw,y_dot,z_dot,roll_dot,yaw_dot,spin_rate,s_left,s_right,angle_left,angle_right,"
         "normal_force_left,normal_force_right,model\n";
  out << std::setprecision(17);
  for (const auto& [t, m] : history) {
    out << m.t << ',' << m.y << ',' << m.z << ',' << m.roll << ',' << m.yaw << ',' << m.y_dot << ',' << m.z_dot << ','
        << m.roll_dot << ',' << m.yaw_dot << ',' << m.spin_rate << ',' << m.s_wheel[0] << ',' << m.s_wheel[1] << ','
        << m.contact_angle[0] << ',' << m.contact_angle[1] << ',' << m.normal_force[0] << ',' << m.normal_force[1]
        << ',' << m.model << '\n';
  }
  if (!out) throw std::runtime_error(path + ": write error");
}

int run_run(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs{
      {"--model", true, "contact model to start with: onepoint, interp, multipoint or spline", ""},
      {"--summary", true, "write the run summary here (JSON)", ""},
      {"--t-end", true, "simulated end time [s]", "2"},
      {"--params", true, "run parameter file (JSON, docs/dynamics.md); options override it", "the benchmark"},
      {"--speed", true, "forward speed [m/s]", "30"},
      {"--vertical-force", true, "external vertical load, downward [N]", "154715"},
      {"--lateral-force", true, "external lateral load, towards +y (left rail) [N]", "-20000"},
      {"--y0", true, "initial lateral shift [m]", "0"},
      {"--yaw0", true, "initial yaw angle [rad]", "0"},
      {"--suspension", true, "benchmark or none (free but for the constant speed)", "benchmark"},
      {"--swap-at", true, "swap the model at the first step at or after simulated times: T:M[,T2:M2...]", "none"},
      {"--history", true, "write the state at every output period here (CSV)", "none"},
      {"--output-period", true, "simulated time between states [s]", "0.001"},
      {"--rtol", true, "relative tolerance of the integrator [-]", "1e-6"},
      {"--in-process", false, "the dynamics evaluates the contact model itself (comparison only)", ""},
      {"--run-id", true, "name of the run", "run-<pid>"},
      {"--timeout", true, "contact query timeout per attempt [s]", "0.2"},
      {"--retries", true, "contact query re-sends per round", "3"},
      {"--contact-wait", true, "longest wait for a (restarted) contact service [s]", "10"},
  };
  for (auto& spec : service_start_option_specs()) specs.push_back(spec);
  for (auto& spec : profile_option_specs()) specs.push_back(spec);
  const Options o("run", "--model M --summary FILE.json [options]", specs, args);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nRuns the rigid wheelset on straight track (wrc-dynamicsd, SUNDIALS IDA) with contact model M,\n"
                 "from the paper's benchmark parameters (or --params FILE; the options override both), and\n"
                 "writes the summary (final state, wall time, integrator and contact counters, swaps). Services\n"
                 "that are not running are started for the run and stopped after it. `wrc swap M` from another\n"
                 "terminal swaps the model at the next step; --swap-at T:M reproduces such a swap.\n";
    return 0;
  }
  protocol::RunRequest request;
  request.model = o.choice("--model", contact_model_names(), "");
  if (request.model.empty()) throw UsageError("--model is required (onepoint, interp, multipoint or spline)");
  const std::string summary_path = o.required_text("--summary");
  RunSpec& spec = request.spec;
  if (o.has("--params")) apply_run_parameter_file(o.text("--params"), spec);
  spec.integrator.t_end = o.number("--t-end", spec.integrator.t_end, 1e-6, 1e6);
  spec.wheelset.speed = o.number("--speed", spec.wheelset.speed, 1e-3, 200.0);
  spec.wheelset.vertical_force = o.number("--vertical-force", spec.wheelset.vertical_force, -1e7, 1e7);
  spec.wheelset.lateral_force = o.number("--lateral-force", spec.wheelset.lateral_force, -1e7, 1e7);
  spec.initial.y = o.number("--y0", spec.initial.y, -0.05, 0.05);
  spec.initial.yaw = o.number("--yaw0", spec.initial.yaw, -0.06, 0.06);
  if (o.has("--suspension")) {
    spec.wheelset.suspension = o.choice("--suspension", {"benchmark", "none"}, "benchmark") == "none"
                                   ? PrimarySuspension::none()
                                   : PrimarySuspension::benchmark();
  }
  spec.integrator.output_period = o.number("--output-period", spec.integrator.output_period, 1e-6, 1e3);
  spec.integrator.relative_tolerance = o.number("--rtol", spec.integrator.relative_tolerance, 1e-12, 0.1);
  spec.validate();
  if (o.has("--swap-at")) request.swaps = parse_swaps(o.text("--swap-at"), spec.integrator.t_end);
  request.in_process = o.has("--in-process");
  request.run_id = o.text("--run-id", "run-" + std::to_string(::getpid()));
  request.contact_timeout = o.number("--timeout", 0.2, 1e-3, 60.0);
  request.contact_retries = o.integer("--retries", 3, 0, 100);
  request.contact_wait = o.number("--contact-wait", 10.0, 0.0, 3600.0);
  request.geometry = geometry_spec_from_options(o);
  const std::string key = geometry_key(request.geometry);

  CommandBus session(o, "run");
  bus::ShutdownSignal::install();
  handle_until(*session.lcm, bus::monotonic_seconds() + kServiceDiscoveryTime, [] { return false; });

  const StartContext context = start_context_from(o, "run", "r" + std::to_string(::getpid()));
  std::vector<std::unique_ptr<StartedService>> started;
  auto keep = [&](std::unique_ptr<StartedService> s) {
    if (s) started.push_back(std::move(s));
  };
  keep(ensure_service(*session.lcm, session.monitor, context, "dynamicsd", "", "wrc-dynamicsd", {}));
  if (!request.in_process) {
    std::vector<std::string> models{request.model};
    for (const auto& s : request.swaps) models.push_back(s.model);
    std::sort(models.begin(), models.end());
    models.erase(std::unique(models.begin(), models.end()), models.end());
    bool needs_geometry = false;
    for (const std::string& m : models) needs_geometry = needs_geometry || contact_model_entry(m).needs_data;
    if (needs_geometry)
      keep(ensure_service(*session.lcm, session.monitor, context, "geometryd", "", "wrc-geometryd", {}));
    for (const std::string& m : models) {
      std::vector<std::string> service_args{"--model", m};
      for (auto& a : geometry_arguments(request.geometry)) service_args.push_back(a);
      keep(ensure_service(*session.lcm, session.monitor, context, m, key, "wrc-contactd", service_args));
    }
  }

  // Listen to the run, then start it.
  run_command_t command = protocol::to_message(request);
  command.request_id = static_cast<std::int64_t>(bus::wall_utime());
  command.geometry_key = key;
  std::map<double, wheelset_state_t> history;
  std::optional<run_summary_t> summary;
  bool acknowledged = false;
  double last_heard = bus::monotonic_seconds();
  ProgressBar bar("run " + request.model);
  std::optional<integrator_stats_t> stats;
  std::string status_line;
  bus::GuardedSubscription<wheelset_state_t> states(
      *session.lcm, session.names.name(bus::channel::kWheelsetState), "run history",
      [&](const wheelset_state_t& m, const bus::ReceivedMessage&) {
        if (m.run_id == request.run_id) history[m.t] = m;
      }, 10000);
  bus::GuardedSubscription<run_status_t> status(
      *session.lcm, session.names.name(bus::channel::kRunStatus), "run status",
      [&](const run_status_t& m, const bus::ReceivedMessage&) {
        if (m.request_id != command.request_id) return;
        acknowledged = true;
        last_heard = bus::monotonic_seconds();
        status_line = m.model;
      });
  bus::GuardedSubscription<integrator_stats_t> counters(
      *session.lcm, session.names.name(bus::channel::kIntegratorStats), "run counters",
      [&](const integrator_stats_t& m, const bus::ReceivedMessage&) {
        if (m.run_id == request.run_id) stats = m;
      });
  bus::GuardedSubscription<run_summary_t> summaries(
      *session.lcm, session.names.name(bus::channel::kRunSummary), "run summary",
      [&](const run_summary_t& m, const bus::ReceivedMessage&) {
        if (m.request_id == command.request_id) summary = m;
      });
  bus::HeaderStamper stamper(bus::sender_name("wrc-run", request.run_id));
  auto send = [&](run_command_t& c) {
    stamper.stamp(c.header);
    bus::publish_signed(*session.lcm, session.names.name(bus::channel::kRunCommand), c);
  };
  bool stop_sent = false;
  double next_send = 0.0;
  while (!summary) {
    const double now = bus::monotonic_seconds();
    if (!acknowledged && now >= next_send) {
      send(command);
      next_send = now + kCommandRepeat;
    }
    if (bus::ShutdownSignal::requested() && !stop_sent) {
      run_command_t stop{};
      stop.request_id = command.request_id + 1;
      stop.run_id = request.run_id;
      stop.command = run_command_t::STOP;
      send(stop);
      stop_sent = true;
      std::cerr << "\nrun: stopping " << request.run_id << "\n";
    }
    session.lcm->handleTimeout(50);
    if (bus::monotonic_seconds() - last_heard > kSilenceLimit) {
      throw std::runtime_error("no status of run " + request.run_id + " for " + std::to_string(kSilenceLimit) +
                               " s: the dynamics service is gone" +
                               (started.empty() ? std::string() : " (its log: " + started.front()->log() + ")"));
    }
    if (stats) {
      std::ostringstream stage;
      stage << "t = " << std::fixed << std::setprecision(3) << stats->t << " s, " << stats->steps << " steps, "
            << stats->restarts << " restarts, " << status_line;
      bar.update(static_cast<long>(stats->t / spec.integrator.t_end * 1000.0), 1000, stage.str());
    }
  }
  bar.finish();
  std::ofstream out(summary_path);
  if (!out) throw std::runtime_error(summary_path + ": cannot write the summary");
  out << summary_json(*summary, request, key).dump(2) << "\n";
  if (!out) throw std::runtime_error(summary_path + ": write error");
  if (o.has("--history")) write_history(o.text("--history"), history);
  std::cerr << "run: " << request.run_id << " " << protocol::run_state_name(summary->state) << " at t = "
            << summary->t_end << " s with " << summary->model << ": y = " << summary->y << " m, yaw = " << summary->yaw
            << " rad; " << summary->wall_time << " s wall, " << summary->stats.steps << " steps, "
            << summary->stats.restarts << " restarts"
            << (summary->message.empty() ? "" : " (" + summary->message + ")") << "\n";
  if (summary->stats.two_point_entries > 0)
    std::cerr << "run: rigid two-point contact (sliding between two equally low minima) entered "
              << summary->stats.two_point_entries << " times, " << summary->stats.two_point_time << " s in all\n";
  if (summary->stats.floored_patches > 0)
    std::cerr << "run: conformal contact at " << summary->stats.floored_patches << " patches of accepted steps ("
              << summary->stats.floored_time << " s): the lateral curvature was floored, Hertz does not hold there\n";
  const bool ok = summary->state == run_status_t::FINISHED;
  for (auto& s : started) ok ? s->stop_and_forget() : s->stop();
  return ok ? 0 : 1;
}

const CommandRegistrar registrar{
    {"run", "a wheelset run on wrc-dynamicsd (services started when none run); summary as JSON", run_run}};

}  // namespace
}  // namespace wrc::cli
