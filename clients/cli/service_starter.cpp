// SPDX-License-Identifier: Apache-2.0
#include "cli/service_starter.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>

#include "bus/auth/bus_auth.hpp"
#include "bus/process/build_paths.hpp"
#include "bus/process/spawn_child.hpp"
#include "bus/process/stop_children.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/service/service_options.hpp"
#include "bus/transport/clock.hpp"
#include "cli/log_cleanup.hpp"

namespace wrc::cli {

StartedService::StartedService(const std::string& path, const std::vector<std::string>& args, std::string log)
    : log_(std::move(log)) {
  std::vector<std::string> words{path};
  words.insert(words.end(), args.begin(), args.end());
  remove_on_signal(log_);  // before the fork: a signal right after it finds the log registered
  pid_ = bus::spawn_tied_child(words, SIGTERM, log_);  // the service drains when the command dies
  if (pid_ < 0) {
    keep_on_signal(log_);
    throw std::runtime_error("fork failed for " + path);
  }
}

StartedService::~StartedService() { stop(); }

bool StartedService::alive() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) {
    pid_ = -1;
    return false;
  }
  return true;
}

void StartedService::stop() {
  keep_on_signal(log_);  // stopped: the caller decides whether its log stays
  if (!alive()) return;
  bus::stop_children({pid_}, 5.0);
  pid_ = -1;
}

void StartedService::stop_and_forget() {
  stop();
  std::error_code ignored;
  std::filesystem::remove(log_, ignored);
}

std::string tail_of(const std::string& path) {
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
  return text;
}

bool handle_until(lcm::LCM& lcm, double deadline, const std::function<bool()>& done) {
  while (!done()) {
    const double left = deadline - bus::monotonic_seconds();
    if (left <= 0.0) return false;
    lcm.handleTimeout(static_cast<int>(std::ceil(std::min(left, 0.05) * 1e3)));
  }
  return true;
}

std::optional<bus::ServiceStatus> pick_service(const bus::HeartbeatMonitor& monitor, const std::string& model,
                                               const std::string& geometry_key, const std::string& instance,
                                               bool ready) {
  for (const auto& s : monitor.services(bus::monotonic_seconds())) {  // sorted by model, instance
    if (s.last.model != model || !s.alive) continue;
    if (!geometry_key.empty() && s.last.geometry_key != geometry_key) continue;
    if (!instance.empty() && s.last.instance != instance) continue;
    if (ready ? s.available() : s.last.state == wrc::heartbeat_t::STARTING) return s;
  }
  return std::nullopt;
}

std::optional<bus::ServiceStatus> discover_service(lcm::LCM& lcm, const bus::HeartbeatMonitor& monitor,
                                                   const std::string& model, const std::string& geometry_key,
                                                   const std::string& instance, double window) {
  const double t0 = bus::monotonic_seconds();
  handle_until(lcm, t0 + window, [&] {
    const std::optional<bus::ServiceStatus> found = pick_service(monitor, model, geometry_key, instance, true);
    if (!found) return false;
    if (!instance.empty()) return true;
    // Every instance beating at least as often as the slowest one heard (or the default period)
    // has beaten once since t0.
    double period = bus::ServiceOptions{}.heartbeat_period;
    for (const auto& s : monitor.services(bus::monotonic_seconds()))
      if (s.last.model == model && s.alive) period = std::max(period, s.last.period);
    return bus::monotonic_seconds() >= t0 + kDiscoveryPeriodMargin * period;
  });
  return pick_service(monitor, model, geometry_key, instance, true);
}

std::vector<OptionSpec> service_start_option_specs() {
  return {{"--start-timeout", true, "wait for a started service to be READY [s]", "300", NumberRange{0.1, 3600.0}},
          {"--channel-prefix", true, "channel prefix of the simulation", "none"},
          {"--lcm-url", true, "LCM URL", "LCM's default"},
          {"--bus-key", true, "bus key file (created when missing)", "$WRC_BUS_KEY, else ~/.config/wrc/bus.key"},
          {"--build-dir", true, "build tree holding the services", "this build"}};
}

StartContext start_context_from(const Options& o, const std::string& command, const std::string& instance) {
  StartContext context;
  context.command = command;
  context.build_dir = o.text("--build-dir", bus::build_dir());
  context.instance = instance;
  if (o.has("--channel-prefix")) context.bus_args.insert(context.bus_args.end(), {"--channel-prefix", o.text("--channel-prefix")});
  if (o.has("--lcm-url")) context.bus_args.insert(context.bus_args.end(), {"--lcm-url", o.text("--lcm-url")});
  context.start_timeout = o.number("--start-timeout");
  return context;
}

namespace {

// The bus key must exist before LCM is opened: open_lcm() loads it.
std::unique_ptr<lcm::LCM> open_with_key(const Options& o, const std::string& command) {
  bus::prepare_bus_key(o.text("--bus-key"), command);
  return bus::open_lcm(o.text("--lcm-url"));
}

}  // namespace

CommandBus::CommandBus(const Options& o, const std::string& command)
    : names(o.text("--channel-prefix")),
      lcm(open_with_key(o, command)),
      monitor(*lcm, names.name(bus::channel::kHeartbeat)) {}

std::unique_ptr<StartedService> ensure_service(lcm::LCM& lcm, const bus::HeartbeatMonitor& monitor,
                                               const StartContext& context, const std::string& model,
                                               const std::string& geometry_key, const std::string& executable,
                                               std::vector<std::string> args, const std::string& instance) {
  if (pick_service(monitor, model, geometry_key, instance, true)) return nullptr;
  if (pick_service(monitor, model, geometry_key, instance, false)) {
    std::cerr << context.command << ": a " << model << " service is starting; waiting for it\n";
    if (handle_until(lcm, bus::monotonic_seconds() + context.start_timeout,
                     [&] { return pick_service(monitor, model, geometry_key, instance, true).has_value(); }))
      return nullptr;
  }
  const std::string name = instance.empty() ? context.instance : instance;
  const auto path = bus::find_service_executable(executable, context.build_dir);
  if (!path) throw std::runtime_error("no " + model + " service runs and " + executable + " is not built in " +
                                      context.build_dir);
  args.insert(args.end(), {"--instance", name, "--heartbeat-period", "0.2"});
  args.insert(args.end(), context.bus_args.begin(), context.bus_args.end());
  const std::string log = (std::filesystem::temp_directory_path() /
                           ("wrc-" + context.command + "-" + model + "-" + name + ".log"))
                              .string();
  std::cerr << context.command << ": no " << model << " service heard; starting " << *path << " (log " << log
            << ")\n";
  auto started = std::make_unique<StartedService>(*path, args, log);
  const double t0 = bus::monotonic_seconds();
  handle_until(lcm, t0 + context.start_timeout, [&] {
    return pick_service(monitor, model, geometry_key, name, true).has_value() || !started->alive();
  });
  if (!pick_service(monitor, model, geometry_key, name, true)) {
    const bool died = !started->alive();
    throw std::runtime_error("the started " + model + " service " +
                             (died ? std::string("exited") : "was not READY in time") + "; its log:\n" +
                             tail_of(log));
  }
  return started;
}

}  // namespace wrc::cli
