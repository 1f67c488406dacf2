// SPDX-License-Identifier: Apache-2.0
// wrc launch [services...]: starts the services of a launch profile and supervises them until
// Ctrl-C or SIGTERM: restart with back-off when one dies, kill and restart when its heartbeats
// stop (hung or SIGSTOPped), every child stopped on exit. Creates the bus key on first use
// (bus/auth/bus_key.hpp) and hands its path to the services in $WRC_BUS_KEY.

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include "bus/auth/bus_auth.hpp"
#include "bus/process/build_paths.hpp"
#include "bus/process/launch_profile.hpp"
#include "bus/process/process_supervisor.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_monitor.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"

namespace wrc::cli {
namespace {

std::string default_profile() {
  const std::string root = bus::source_dir();
  return (std::filesystem::path(root.empty() ? "." : root) / "profiles/launch/default.txt").string();
}

int run_launch(const std::vector<std::string>& args) {
  Options options("launch", "[services...] [options]",
                  {{"--profile", true, "launch profile file", "profiles/launch/default.txt"},
                   {"--channel-prefix", true, "channel prefix passed to every service", "none"},
                   {"--lcm-url", true, "LCM URL passed to every service", "LCM's default"},
                   {"--bus-key", true, "bus key file, created when missing", "$WRC_BUS_KEY, else ~/.config/wrc/bus.key"},
                   {"--hang-periods", true, "restart a service silent for this many of its heartbeat periods", "2",
                       NumberRange{1.0, 100.0}},
                   {"--build-dir", true, "build tree holding the service executables", "this build"},
                   {"--grace", true, "wait after SIGTERM before SIGKILL on stop [s]", "3", NumberRange{0.0, 600.0}},
                   {"--backoff-min", true, "first restart delay [s], doubles per quick failure", "0.25",
                       NumberRange{0.01, 600.0}},
                   {"--backoff-max", true, "largest restart delay [s]", "8"},
                   {"--list", false, "print the profile's services and whether they are built, then exit", ""}},
                  args, Positional::kAllowed);
  if (options.help_requested()) {
    std::cout << options.help()
              << "\nStarts the named services of the profile (all when none is named), restarts a\n"
                 "service that dies or whose heartbeats stop, and stops them all on Ctrl-C or SIGTERM.\n"
                 "The bus key is created on first use (mode 0600); copy it to the other machines of the bus.\n";
    return 0;
  }
  const std::string profile_path = options.text("--profile", default_profile());
  const std::string build = options.text("--build-dir", bus::build_dir());
  bus::SupervisorPolicy policy;
  policy.grace = options.number("--grace");
  policy.backoff_min = options.number("--backoff-min");
  policy.backoff_max = options.number_within("--backoff-max", {policy.backoff_min, 3600.0});
  policy.hang_periods = options.number("--hang-periods");

  const auto selected = bus::select_services(bus::read_launch_profile(profile_path), options.positional());
  std::vector<bus::ChildSpec> children;
  for (const auto& entry : selected) {
    const auto path = bus::find_service_executable(entry.executable, build);
    if (options.has("--list")) {
      std::cout << entry.name << "\t" << entry.executable << "\t" << (path ? *path : "not built") << "\n";
      continue;
    }
    if (!path) {
      std::cerr << "launch: skipping " << entry.name << ": " << entry.executable
                << " is not built (looked in " << build << "/services)\n";
      continue;
    }
    bus::ChildSpec spec{entry.name, *path, entry.args};
    if (options.has("--channel-prefix")) {
      spec.args.push_back("--channel-prefix");
      spec.args.push_back(options.text("--channel-prefix"));
    }
    if (options.has("--lcm-url")) {
      spec.args.push_back("--lcm-url");
      spec.args.push_back(options.text("--lcm-url"));
    }
    children.push_back(std::move(spec));
  }
  if (options.has("--list")) return 0;
  if (children.empty()) {
    std::cerr << "launch: none of the requested services is built; nothing to start\n";
    return 1;
  }

  bus::prepare_bus_key(options.text("--bus-key"), "launch");
  auto lcm = bus::open_lcm(options.text("--lcm-url"));
  const bus::ChannelNames names(options.text("--channel-prefix"));
  bus::HeartbeatMonitor heartbeats(*lcm, names.name(bus::channel::kHeartbeat));

  bus::ShutdownSignal::install();
  bus::ProcessSupervisor supervisor(std::move(children), policy, std::cerr);
  // Each heartbeat as it arrives (the supervisor matches it to a child by pid and identity), not
  // the whole table every turn: a flood can fill the table with 512 entries.
  heartbeats.set_observer([&supervisor](const bus::ServiceStatus& s) {
    supervisor.heartbeat_seen(s.last.pid, s.nonce, s.last.period, s.last_seen);
  });
  supervisor.start_all();
  while (!bus::ShutdownSignal::requested()) {
    lcm->handleTimeout(20);  // heartbeats of the children (and of everyone else)
    while (lcm->handleTimeout(0) > 0) {
    }
    supervisor.poll();
  }
  std::cerr << "launch: signal " << bus::ShutdownSignal::signal_number() << " received, stopping "
            << supervisor.children().size() << " services\n";
  supervisor.stop_all();
  std::cerr << "launch: all services stopped\n";
  return 0;
}

const CommandRegistrar registrar{
    {"launch", "start and supervise the services (restart on failure, stop all on Ctrl-C)", run_launch}};

}  // namespace
}  // namespace wrc::cli
