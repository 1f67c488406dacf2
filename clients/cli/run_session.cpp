// SPDX-License-Identifier: Apache-2.0
#include "cli/run_session.hpp"

#include <unistd.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "bus/auth/signed_publish.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "cli/progress_bar.hpp"
#include "cli/run_outputs.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/models/contact_model_factory.hpp"
#include "options/fit_options.hpp"
#include "protocol/contact/contact_service_key.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/run_status_t.hpp"

namespace wrc::cli {
namespace {

constexpr double kCommandRepeat = 0.5;  // [s] re-send the START until the dynamics acknowledges it
constexpr double kSilenceLimit = 30.0;  // [s] without any status of the run: the dynamics is gone
// [s] Without a status from the process running the run while its heartbeats have stopped too
// (3 missed periods, bus::HeartbeatMonitor): that process is gone, the run is sent again. Statuses
// come every 0.5 s (wrc-dynamicsd's kStatusPeriod), heartbeats every period, so a lossy bus alone
// loses both for this long with a chance of about 0.05^7 at 5 % loss; a false alarm costs nothing
// but a count (a live process ignores a START whose request id it has seen).
constexpr double kRunnerSilence = 2.0;

// Whether the process with the sender nonce runner beats as a live wrc-dynamicsd (monitor's view at now [s]).
bool dynamics_alive(const bus::HeartbeatMonitor& monitor, std::uint64_t runner, double now) {
  for (const bus::ServiceStatus& s : monitor.services(now))
    if (s.nonce == runner && s.last.model == "dynamicsd" && s.alive) return true;
  return false;
}

// Whether any wrc-dynamicsd (of that instance name, when one is given) beats, READY or not.
bool any_dynamics_alive(const bus::HeartbeatMonitor& monitor, const std::string& instance, double now) {
  for (const bus::ServiceStatus& s : monitor.services(now))
    if (s.last.model == "dynamicsd" && s.alive && (instance.empty() || s.last.instance == instance)) return true;
  return false;
}

}  // namespace

RunSession::RunSession(const Options& options, protocol::RunRequest request)
    : options_(options), request_(std::move(request)), key_(geometry_key(request_.geometry)), session_(options, "run") {
  bus::ShutdownSignal::install();
  handle_until(*session_.lcm, bus::monotonic_seconds() + kServiceDiscoveryTime, [] { return false; });
}

RunSession::~RunSession() = default;

void RunSession::start_services() {
  const StartContext context = start_context_from(options_, "run", "r" + std::to_string(::getpid()));
  auto keep = [&](std::unique_ptr<StartedService> s) {
    if (s) started_.push_back(std::move(s));
  };
  keep(ensure_service(*session_.lcm, session_.monitor, context, "dynamicsd", "", "wrc-dynamicsd", {},
                      request_.dynamics_instance));
  if (!started_.empty()) own_dynamics_ = started_.back().get();
  if (request_.in_process) return;
  std::vector<std::string> models{request_.model};
  for (const auto& s : request_.swaps) models.push_back(s.model);
  std::sort(models.begin(), models.end());
  models.erase(std::unique(models.begin(), models.end()), models.end());
  bool needs_geometry = false;
  for (const std::string& m : models) needs_geometry = needs_geometry || contact_model_entry(m).needs_data;
  if (needs_geometry)
    keep(ensure_service(*session_.lcm, session_.monitor, context, "geometryd", "", "wrc-geometryd", {}));
  for (const std::string& m : models) {
    std::vector<std::string> service_args{"--model", m};
    for (auto& a : geometry_arguments(request_.geometry)) service_args.push_back(a);
    // A spline service fitted as the run asks (its key says which fit it serves).
    if (contact_model_entry(m).needs_data)
      for (auto& a : fit_arguments(options_)) service_args.push_back(a);
    const std::string key = protocol::contact_service_key(m, request_.geometry, request_.spline_fit);
    keep(ensure_service(*session_.lcm, session_.monitor, context, m, key, "wrc-contactd", service_args));
  }
}

const run_summary_t& RunSession::run() {
  // Listen to the run, then start it.
  lcm::LCM& lcm = *session_.lcm;
  run_command_t command = protocol::to_message(request_);
  command.request_id = static_cast<std::int64_t>(bus::wall_utime());
  command.geometry_key = key_;
  bool acknowledged = false;
  std::uint64_t runner = 0;  // sender nonce of the process running the run (its acknowledgement)
  double last_heard = bus::monotonic_seconds();
  ProgressBar bar("run " + request_.model);
  std::optional<integrator_stats_t> stats;
  std::string status_line;
  const std::string& run_id = request_.run_id;
  bus::GuardedSubscription<wheelset_states_t> states(
      lcm, session_.names.name(bus::channel::kWheelsetState), "run history",
      [&](const wheelset_states_t& batch, const bus::ReceivedMessage&) {
        if (batch.run_id != run_id) return;
        for (const wheelset_state_t& m : batch.states)
          if (m.run_id == run_id) history_[{m.t, m.wheelset}] = m;
      }, 1000);
  bus::GuardedSubscription<run_status_t> status(
      lcm, session_.names.name(bus::channel::kRunStatus), "run status",
      [&](const run_status_t& m, const bus::ReceivedMessage& info) {
        // The request id is the wall clock's microsecond: runs started at once (a sweep's jobs) can
        // share it, so the run id must match too.
        if (m.request_id != command.request_id || m.run_id != run_id) return;
        if (!acknowledged) runner = info.origin.nonce;
        acknowledged = true;
        if (info.origin.nonce == runner) last_heard = bus::monotonic_seconds();
        status_line = m.model;
      });
  bus::GuardedSubscription<integrator_stats_t> counters(
      lcm, session_.names.name(bus::channel::kIntegratorStats), "run counters",
      [&](const integrator_stats_t& m, const bus::ReceivedMessage&) {
        if (m.run_id == run_id) stats = m;
      });
  bus::GuardedSubscription<run_summary_t> summaries(
      lcm, session_.names.name(bus::channel::kRunSummary), "run summary",
      [&](const run_summary_t& m, const bus::ReceivedMessage&) {
        if (m.request_id == command.request_id && m.run_id == run_id) summary_ = m;
      });
  bus::HeaderStamper stamper(bus::sender_name("wrc-run", run_id));
  auto send = [&](run_command_t& c) {
    stamper.stamp(c.header);
    bus::publish_signed(lcm, session_.names.name(bus::channel::kRunCommand), c);
  };
  bool stop_sent = false;
  bool ever_acknowledged = false;
  double next_send = 0.0;
  while (!summary_) {
    const double now = bus::monotonic_seconds();
    ever_acknowledged = ever_acknowledged || acknowledged;
    if (!acknowledged && now >= next_send) {
      // The dynamics heard at the start ended before it took the run (another command's service,
      // busy with that command's run and stopped by it when it ended): one is started for this run.
      if (!ever_acknowledged && !own_dynamics_ && !any_dynamics_alive(session_.monitor, request_.dynamics_instance, now)) {
        std::cerr << "\nrun: the wrc-dynamicsd heard at the start has ended before taking the run; starting one\n";
        start_own_dynamics();
        last_heard = bus::monotonic_seconds();
      }
      send(command);
      next_send = now + kCommandRepeat;
    }
    if (bus::ShutdownSignal::requested() && !stop_sent) {
      run_command_t stop{};
      stop.request_id = command.request_id + 1;
      stop.run_id = run_id;
      stop.dynamics_instance = request_.dynamics_instance;
      stop.command = run_command_t::STOP;
      send(stop);
      stop_sent = true;
      std::cerr << "\nrun: stopping " << run_id << "\n";
    }
    lcm.handleTimeout(50);
    if (acknowledged && !stop_sent && bus::monotonic_seconds() - last_heard > kRunnerSilence &&
        !dynamics_alive(session_.monitor, runner, bus::monotonic_seconds())) {
      // The process running the run is gone (killed, crashed, its machine lost): the run is sent
      // again, to the instance that takes over (restarted by the launcher, or by this command when
      // it started the service). The run is deterministic, so it ends as the lost one would have.
      restart_own_dynamics();
      acknowledged = false;
      next_send = 0.0;
      ++resends_;
      std::cerr << "\nrun: the wrc-dynamicsd running " << run_id << " is gone; sending the run again (#" << resends_
                << ")\n";
    }
    if (bus::monotonic_seconds() - last_heard > kSilenceLimit) {
      throw std::runtime_error("no status of run " + run_id + " for " + std::to_string(kSilenceLimit) +
                               " s: the dynamics service is gone" +
                               (started_.empty() ? std::string() : " (its log: " + started_.front()->log() + ")"));
    }
    if (stats) {
      std::ostringstream stage;
      stage << "t = " << std::fixed << std::setprecision(3) << stats->t << " s, " << stats->steps << " steps, "
            << stats->restarts << " restarts, " << status_line;
      bar.update(static_cast<long>(stats->t / request_.spec.integrator.t_end * 1000.0), 1000, stage.str());
    }
  }
  bar.finish();
  return *summary_;
}

void RunSession::restart_own_dynamics() {
  if (!own_dynamics_ || own_dynamics_->alive()) return;
  std::cerr << "\nrun: the wrc-dynamicsd it started has ended (log: " << own_dynamics_->log() << "); starting another\n";
  start_own_dynamics();
}

void RunSession::start_own_dynamics() {
  const StartContext context = start_context_from(options_, "run", "r" + std::to_string(::getpid()));
  std::unique_ptr<StartedService> again = ensure_service(*session_.lcm, session_.monitor, context, "dynamicsd", "",
                                                          "wrc-dynamicsd", {}, request_.dynamics_instance);
  own_dynamics_ = again.get();
  if (again) started_.push_back(std::move(again));
}

int RunSession::finish() {
  const run_summary_t& s = *summary_;
  nlohmann::json summary = summary_json(s, request_, key_);
  summary["run_resends"] = resends_;
  write_summary(options_.required_text("--summary"), summary);
  if (options_.has("--history")) write_history(options_.text("--history"), history_);
  std::cerr << "run: " << request_.run_id << " " << protocol::run_state_name(s.state) << " at t = " << s.t_end
            << " s with " << s.model << ": y = " << s.y << " m, yaw = " << s.yaw << " rad; " << s.wall_time
            << " s wall, " << s.stats.steps << " steps, " << s.stats.restarts << " restarts"
            << (s.message.empty() ? "" : " (" + s.message + ")") << "\n";
  if (resends_ > 0)
    std::cerr << "run: sent again " << resends_ << (resends_ == 1 ? " time" : " times")
              << " after losing the dynamics service running it, from the start each time\n";
  if (s.stats.two_point_entries > 0)
    std::cerr << "run: rigid two-point contact (sliding between two equally low minima) entered "
              << s.stats.two_point_entries << " times, " << s.stats.two_point_time << " s in all\n";
  if (s.stats.floored_patches > 0)
    std::cerr << "run: conformal contact at " << s.stats.floored_patches << " patches of accepted steps ("
              << s.stats.floored_time << " s): the lateral curvature was floored, Hertz does not hold there\n";
  const bool ok = s.state == run_status_t::FINISHED;
  for (auto& service : started_) ok ? service->stop_and_forget() : service->stop();
  started_.clear();
  return ok ? 0 : 1;
}

}  // namespace wrc::cli
