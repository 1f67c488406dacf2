// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/dynamics_service.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "bus/auth/signed_publish.hpp"
#include "bus/service/log_text.hpp"
#include "bus/transport/clock.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "dynamicsd/bus_contact.hpp"
#include "dynamicsd/run_end_log.hpp"
#include "protocol/contact/contact_service_key.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/run_status_t.hpp"
#include "wrc/wheelset_states_t.hpp"

namespace wrc::dynamics {
namespace {

constexpr double kStatusPeriod = 0.5;  // [s] wall time between RUN_STATUS / INTEGRATOR_STATS

}  // namespace

DynamicsService::DynamicsService(lcm::LCM& lcm, const std::string& lcm_url, const bus::ChannelNames& names,
                                 const std::string& instance, const std::string& sender, std::function<void()> keepalive)
    : lcm_(lcm),
      names_(names),
      instance_(instance),
      created_(bus::monotonic_seconds()),
      keepalive_(std::move(keepalive)),
      stamper_(sender),
      monitor_(lcm, names.name(bus::channel::kHeartbeat)),
      clients_(lcm, lcm_url, names, sender),
      states_([this](wheelset_states_t& batch) { publish(bus::channel::kWheelsetState, batch); }) {
  commands_ = std::make_unique<bus::GuardedSubscription<run_command_t>>(
      lcm_, names_.name(bus::channel::kRunCommand), "dynamics commands",
      [this](const run_command_t& c, const bus::ReceivedMessage&) { on_command(c); });
  selects_ = std::make_unique<bus::GuardedSubscription<contact_select_t>>(
      lcm_, names_.name(bus::channel::kContactSelect), "dynamics swaps",
      [this](const contact_select_t& s, const bus::ReceivedMessage& info) { on_select(s, info.origin.nonce); });
}

template <class Message>
void DynamicsService::publish(const char* base, Message& message) {
  stamper_.stamp(message.header);
  bus::publish_signed(lcm_, names_.name(base), message);
}

void DynamicsService::on_command(const run_command_t& command) {
  if (serving_ && !serving_()) return;  // a duplicate stays passive
  if (!command.dynamics_instance.empty() && command.dynamics_instance != instance_) return;  // for another one
  // A run that named this dynamics (one of a sweep's, say) is not replaced or stopped by a command
  // that names none: that one is for the dynamics that run whatever they hear.
  if (command.dynamics_instance.empty() && running() && !request_.dynamics_instance.empty()) return;
  if (command.request_id <= 0 || command.request_id == last_request_id_) return;  // repeats of one command
  last_request_id_ = command.request_id;
  pending_command_ = command;  // acted on at the next step boundary (poll)
}

void DynamicsService::on_select(const contact_select_t& select, std::uint64_t sender) {
  if (serving_ && !serving_()) return;
  if (select.seq <= 0) return;  // numbers count from 1
  auto it = select_senders_.find(sender);
  if (it != select_senders_.end() && select.seq <= it->second.seq) return;  // a copy of a selection already seen
  if (it == select_senders_.end()) {
    if (select_senders_.size() >= kMaxSelectSenders) {
      select_senders_.erase(std::min_element(select_senders_.begin(), select_senders_.end(),
                                             [](const auto& a, const auto& b) { return a.second.heard < b.second.heard; }));
    }
    it = select_senders_.emplace(sender, SelectSender{}).first;
  }
  it->second = {select.seq, ++selects_heard_};
  pending_select_ = select;
}

std::shared_ptr<ContactEvaluator> DynamicsService::make_contact(const std::string& model) {
  if (request_.in_process) {
    ContactModelData data;
    if (contact_model_entry(model).needs_data) {
      // The fit takes about a second: the heartbeat goes on from its progress reports.
      data.splines = fit_spline_geometry(*geometry_, request_.spline_fit, [this](long, long, const std::string&) {
                       if (keepalive_) keepalive_();
                     }).model;
    }
    return std::make_shared<InProcessContact>(make_contact_model(model, geometry_, {}, data));
  }
  BusContactSettings s;
  s.model = model;
  s.instance = request_.instance;
  s.geometry_key = protocol::contact_service_key(model, request_.geometry, request_.spline_fit);
  s.policy.timeout = request_.contact_timeout;
  s.policy.retries = request_.contact_retries;
  s.wait = request_.contact_wait;
  s.keepalive = keepalive_;
  auto contact = std::make_shared<BusContact>(clients_.client(model), monitor_, names_, s);
  bus_contacts_.push_back(contact);
  return contact;
}

void DynamicsService::add_query_instances(run_summary_t& summary) const {
  std::map<std::string, long> answered;  // "model/instance" -> queries
  for (const auto& contact : bus_contacts_)
    for (const auto& [instance, queries] : contact->instance_queries()) answered[contact->model() + "/" + instance] += queries;
  for (const auto& [name, queries] : answered) {
    if (summary.num_query_instances == kMaxQueryInstances) break;
    summary.query_instances.push_back(name);
    summary.instance_queries.push_back(queries);
    ++summary.num_query_instances;
  }
}

std::unique_ptr<Simulation> DynamicsService::make_wheelset_run(double nominal_radius) {
  auto run = std::make_unique<WheelsetSimulation>(request_.spec, make_contact(request_.model), nominal_radius);
  const std::string run_id = request_.run_id;
  const WheelsetParameters wheelset = request_.spec.wheelset;
  run->on_output([this, run_id, wheelset](const WheelsetSnapshot& s) {
    states_.add(protocol::to_state_message(s, run_id, wheelset), bus::monotonic_seconds());
  });
  wheelset_run_ = run.get();
  return run;
}

std::unique_ptr<Simulation> DynamicsService::make_vehicle_run(double nominal_radius) {
  auto run = std::make_unique<VehicleSimulation>(VehicleRunSpec{*request_.vehicle, request_.spec, std::nullopt},
                                                 make_contact(request_.model), nominal_radius);
  const std::string run_id = request_.run_id;
  VehicleSimulation* vehicle = run.get();
  std::vector<WheelsetParameters> parameters;
  std::vector<double> ahead;  // [m] each wheelset's place ahead of the vehicle's reference point
  for (size_t w = 0; w < vehicle->equations().wheelset_count(); ++w) {
    parameters.push_back(vehicle->wheelset_parameters(w));
    ahead.push_back(vehicle->equations().vehicle().bodies[vehicle->equations().wheelset_body(w)].position[0]);
  }
  run->on_output([this, run_id, vehicle, parameters, ahead](const VehicleSnapshot& s) {
    const double now = bus::monotonic_seconds();
    for (size_t w = 0; w < parameters.size(); ++w)
      states_.add(protocol::to_state_message(vehicle->wheelset_snapshot(s, w), run_id, parameters[w],
                                             static_cast<int>(w), ahead[w]),
                  now);
  });
  vehicle_run_ = vehicle;
  return run;
}

void DynamicsService::start(const run_command_t& command) {
  simulation_.reset();
  wheelset_run_ = nullptr;
  vehicle_run_ = nullptr;
  summary_.reset();
  status_message_.clear();
  bus_contacts_.clear();
  request_id_ = command.request_id;
  try {
    request_ = protocol::from_message(command);
    if (request_.in_process) geometry_ = std::make_shared<const WheelsetGeometry>(make_geometry(request_.geometry));
    const double r0 = request_.geometry.track.nominal_radius;
    states_.start(request_.run_id);
    simulation_ = request_.vehicle ? make_vehicle_run(r0) : make_wheelset_run(r0);
    for (const protocol::ScheduledSwap& swap : request_.swaps) simulation_->schedule_swap(swap.t, make_contact(swap.model));
    wall_start_ = bus::monotonic_seconds();
    std::cerr << "wrc-dynamicsd: run " << bus::log_text(request_.run_id) << " with " << request_.model
              << (request_.in_process ? " (in-process)" : "")
              << (request_.vehicle ? " of vehicle '" + bus::log_text(request_.vehicle->name) + "'" : std::string())
              << " to t = " << request_.spec.integrator.t_end << " s\n";
    simulation_->start();
    if (vehicle_run_ && !vehicle_run_->start_note().empty()) {
      status_message_ = vehicle_run_->start_note();
      std::cerr << "wrc-dynamicsd: " << bus::log_text(status_message_) << "\n";
    }
  } catch (const std::exception& e) {
    simulation_.reset();
    wheelset_run_ = nullptr;
    vehicle_run_ = nullptr;
    states_.discard();
    std::cerr << "wrc-dynamicsd: run " << bus::log_text(command.run_id) << " failed to start: " << bus::log_text(e.what())
              << "\n";
    publish_refusal(command, e.what());
    run_summary_t summary{};
    summary.request_id = command.request_id;
    summary.run_id = command.run_id;
    summary.state = run_status_t::FAILED;
    summary.model = command.model;
    summary.message = e.what();
    summary_ = summary;
    publish(bus::channel::kRunSummary, *summary_);
    return;
  }
  publish_status(true);
}

void DynamicsService::publish_refusal(const run_command_t& command, const std::string& reason) {
  run_status_t status{};
  status.request_id = command.request_id;
  status.run_id = command.run_id;
  status.state = run_status_t::FAILED;
  status.model = command.model;
  status.message = reason;
  publish(bus::channel::kRunStatus, status);
}

void DynamicsService::apply_select() {
  const contact_select_t select = *pending_select_;
  pending_select_.reset();
  if (!running() || (!select.run_id.empty() && select.run_id != request_.run_id)) return;
  if (select.model == simulation_->model()) return;
  try {
    contact_model_entry(select.model);
    if (!request_.in_process) {
      const std::string missing =
          missing_service_reason(monitor_, select.model, select.instance,
                                 protocol::contact_service_key(select.model, request_.geometry, request_.spline_fit));
      if (!missing.empty()) {
        status_message_ = "swap to " + select.model + " refused, keeping " + simulation_->model() + ": " + missing;
        std::cerr << "wrc-dynamicsd: " << bus::log_text(status_message_) << "\n";
        publish_status(true);
        return;
      }
    }
    simulation_->request_swap(make_contact(select.model));
  } catch (const std::exception& e) {
    status_message_ = "swap to " + select.model + " refused: " + e.what();
    publish_status(true);
  }
}

void DynamicsService::finish() {
  states_.flush();  // every sample before the summary that ends the run
  wall_time_ = bus::monotonic_seconds() - wall_start_;
  run_summary_t summary =
      vehicle_run_ ? protocol::to_summary_message(*vehicle_run_, request_.run_id, request_id_, wall_time_)
                   : protocol::to_summary_message(*wheelset_run_, request_.run_id, request_id_, wall_time_);
  if (summary.message.empty()) summary.message = status_message_;
  add_query_instances(summary);
  summary_ = summary;
  publish(bus::channel::kRunSummary, *summary_);
  std::cerr << run_end_log_line(request_.run_id, simulation_->time(), simulation_->message(), wall_time_,
                                simulation_->counters())
            << "\n";
  publish_status(true);
}

void DynamicsService::publish_status(bool force) {
  const double now = bus::monotonic_seconds();
  if (!force && now < next_status_) return;
  next_status_ = now + kStatusPeriod;
  if (!simulation_) {
    if (summary_) publish(bus::channel::kRunSummary, *summary_);
    return;
  }
  run_status_t status{};
  status.request_id = request_id_;
  status.run_id = request_.run_id;
  status.state = protocol::run_state_code(simulation_->state());
  status.t = simulation_->time();
  status.t_end = request_.spec.integrator.t_end;
  status.model = simulation_->model();
  status.instance = request_.instance;
  status.num_switches = static_cast<std::int32_t>(simulation_->swaps().size());
  status.last_switch_time = simulation_->swaps().empty() ? -1.0 : simulation_->swaps().back().t;
  status.message = simulation_->message().empty() ? status_message_ : simulation_->message();
  publish(bus::channel::kRunStatus, status);
  const double wall = running() ? now - wall_start_ : wall_time_;
  integrator_stats_t stats = protocol::to_stats_message(simulation_->counters(), request_.run_id, simulation_->time(), wall);
  publish(bus::channel::kIntegratorStats, stats);
  publish_progress(wall);
  if (!running() && summary_) publish(bus::channel::kRunSummary, *summary_);
}

void DynamicsService::publish_progress(double wall) {
  constexpr long kUnits = 1000;  // progress in thousandths of the simulated interval
  const double t = simulation_->time();
  const double t_end = request_.spec.integrator.t_end;
  const double fraction = t_end > 0.0 ? std::clamp(t / t_end, 0.0, 1.0) : 1.0;
  progress_t p{};
  p.request_id = request_id_;
  p.task = "run " + request_.run_id + " " + simulation_->model();
  p.done = running() ? static_cast<std::int64_t>(fraction * kUnits) : kUnits;
  p.total = kUnits;
  p.elapsed = wall;
  p.remaining = !running() ? 0.0 : fraction > 0.0 ? wall * (1.0 - fraction) / fraction : -1.0;
  const RunCounters c = simulation_->counters();
  std::ostringstream message;
  message << std::setprecision(4) << "t = " << t << " of " << t_end << " s, " << c.steps << " steps, " << c.restarts
          << " restarts";
  if (!running()) message << "; " << protocol::run_state_name(protocol::run_state_code(simulation_->state()));
  p.message = message.str();
  publish(bus::channel::kProgress, p);
}

std::string DynamicsService::activity() const {
  if (!simulation_) return "idle";
  const RunCounters c = simulation_->counters();
  std::ostringstream out;
  out << std::setprecision(4);
  if (running()) {
    out << "run " << request_.run_id << ": " << simulation_->model() << ", t = " << simulation_->time() << " of "
        << request_.spec.integrator.t_end << " s, " << c.steps << " steps, " << c.restarts << " restarts";
  } else {
    out << "idle; last run " << request_.run_id << " " << protocol::run_state_name(protocol::run_state_code(simulation_->state())) << " at t = "
        << simulation_->time() << " s after " << wall_time_ << " s";
  }
  return out.str();
}

bool DynamicsService::discovering(const run_command_t& command) const {
  return command.command == run_command_t::START && command.in_process == 0 &&
         bus::monotonic_seconds() < created_ + kInstanceDiscovery;
}

void DynamicsService::poll(double budget) {
  if (pending_command_ && !discovering(*pending_command_)) {
    const run_command_t command = *pending_command_;
    pending_command_.reset();
    if (command.command == run_command_t::START) {
      if (running()) {
        simulation_->request_stop();
        simulation_->advance();
        finish();
      }
      start(command);
    } else if (command.command == run_command_t::STOP) {
      if (running() && (command.run_id.empty() || command.run_id == request_.run_id)) simulation_->request_stop();
    } else {
      // Neither: the running run (if any) goes on; the sender learns why nothing happened.
      const std::string reason = "command = " + std::to_string(command.command) + " is neither START (" +
                                 std::to_string(run_command_t::START) + ") nor STOP (" +
                                 std::to_string(run_command_t::STOP) + "); ignored";
      std::cerr << "wrc-dynamicsd: " << reason << "\n";
      publish_refusal(command, reason);
    }
  }
  if (pending_select_) apply_select();
  if (simulation_ && simulation_->state() == RunState::kRunning) {
    const double until = bus::monotonic_seconds() + budget;
    bool more = true;
    while (more && bus::monotonic_seconds() < until && !pending_command_ && !pending_select_)
      more = simulation_->advance();
    if (!more) finish();
  }
  states_.tick(bus::monotonic_seconds());
  publish_status(false);
}

}  // namespace wrc::dynamics
