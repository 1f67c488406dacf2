// wrc launch [services...]: starts the services of a launch profile and supervises them until
// Ctrl-C or SIGTERM (restart with back-off when one dies; every child stopped on exit).

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include "bus/build_paths.hpp"
#include "bus/launch_profile.hpp"
#include "bus/process_supervisor.hpp"
#include "bus/shutdown_signal.hpp"
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
                   {"--build-dir", true, "build tree holding the service executables", "this build"},
                   {"--grace", true, "wait after SIGTERM before SIGKILL on stop [s]", "3"},
                   {"--backoff-min", true, "first restart delay [s], doubles per quick failure", "0.25"},
                   {"--backoff-max", true, "largest restart delay [s]", "8"},
                   {"--list", false, "print the profile's services and whether they are built, then exit", ""}},
                  args, Positional::kAllowed);
  if (options.help_requested()) {
    std::cout << options.help()
              << "\nStarts the named services of the profile (all when none is named), restarts a\n"
                 "service that dies, and stops them all on Ctrl-C or SIGTERM.\n";
    return 0;
  }
  const std::string profile_path = options.text("--profile", default_profile());
  const std::string build = options.text("--build-dir", bus::build_dir());
  bus::SupervisorPolicy policy;
  policy.grace = options.number("--grace", 3.0, 0.0, 600.0);
  policy.backoff_min = options.number("--backoff-min", 0.25, 0.01, 600.0);
  policy.backoff_max = options.number("--backoff-max", 8.0, policy.backoff_min, 3600.0);

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

  bus::ShutdownSignal::install();
  bus::ProcessSupervisor supervisor(std::move(children), policy, std::cerr);
  supervisor.start_all();
  while (!bus::ShutdownSignal::requested()) {
    supervisor.poll();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
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
