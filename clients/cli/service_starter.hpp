// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Services a command needs, found by their heartbeats or started from the build tree for the
/// command's lifetime (tied to it: they drain when it dies), with their logs removed after a clean
/// stop.

#include <lcm/lcm-cpp.hpp>
#include <sys/types.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/channels.hpp"
#include "cli/options.hpp"

namespace wrc::cli {

/// A service process this command started. Its log is removed should the command end by a signal
/// before stop() (log_cleanup.hpp).
class StartedService {
 public:
  /// Starts path with args, output to log. @throws std::runtime_error when fork fails.
  StartedService(const std::string& path, const std::vector<std::string>& args, std::string log);
  ~StartedService();
  StartedService(const StartedService&) = delete;
  StartedService& operator=(const StartedService&) = delete;
  pid_t pid() const { return pid_; }
  const std::string& log() const { return log_; }
  bool alive();
  /// SIGTERM, up to 5 s for a clean exit (DRAINING heartbeat), then SIGKILL.
  void stop();
  /// stop() and remove the log.
  void stop_and_forget();

 private:
  pid_t pid_ = -1;
  std::string log_;
};

/// The last 2000 characters of a file.
std::string tail_of(const std::string& path);

/// Dispatches LCM until done() or the deadline [s, monotonic]; false on timeout.
bool handle_until(lcm::LCM& lcm, double deadline, const std::function<bool()>& done);

/// The smallest-named alive instance of model (with geometry_key when not empty, the named
/// instance when not empty), READY (ready) or STARTING.
std::optional<bus::ServiceStatus> pick_service(const bus::HeartbeatMonitor& monitor, const std::string& model,
                                               const std::string& geometry_key, const std::string& instance,
                                               bool ready);

/// Heartbeat periods discover_service() listens after the first match [-]: a little more than one,
/// for the delivery jitter.
inline constexpr double kDiscoveryPeriodMargin = 1.1;

/// The READY instance of model (with geometry_key when not empty) that pick_service() chooses,
/// after listening for up to window [s]: with a named instance, as soon as it is heard; otherwise,
/// once one is heard, until kDiscoveryPeriodMargin times the longest heartbeat period (of the
/// instances of model heard, and the services' default) has passed since the start: every
/// instance beating at least as often has been heard then, so the smallest name is not missed
/// because another one beat first. Never past the window. nullopt: none heard.
std::optional<bus::ServiceStatus> discover_service(lcm::LCM& lcm, const bus::HeartbeatMonitor& monitor,
                                                   const std::string& model, const std::string& geometry_key,
                                                   const std::string& instance, double window);

/// Where services are started and how.
struct StartContext {
  std::string command;      ///< "run", for log lines and file names
  std::string build_dir;    ///< build tree holding the service executables
  std::string instance;     ///< instance name given to started services
  std::vector<std::string> bus_args;  ///< --channel-prefix / --lcm-url passed on
  double start_timeout = 300.0;       ///< [s] wait for READY
};

/// The options of a command that may start services (one list for run, query and fit --service):
/// --start-timeout, --channel-prefix, --lcm-url, --bus-key, --build-dir.
std::vector<OptionSpec> service_start_option_specs();

/// The StartContext those options give: command names the log lines and files, instance is the
/// name given to the services it starts.
StartContext start_context_from(const Options& options, const std::string& command, const std::string& instance);

/// [s] How long a command that may start services listens for the heartbeats of running ones
/// before it starts any.
constexpr double kServiceDiscoveryTime = 1.5;

/// The bus of a command that may start services (run, query, fit --service), from those options:
/// the channel names of --channel-prefix, the bus key of --bus-key prepared first (created on
/// first use; the services it starts use it), LCM on --lcm-url and a heartbeat monitor on it.
struct CommandBus {
  /// command: the command's name for the key's messages ("run").
  CommandBus(const Options& options, const std::string& command);
  bus::ChannelNames names;
  std::unique_ptr<lcm::LCM> lcm;
  bus::HeartbeatMonitor monitor;
};

/// A READY service of model (heartbeat model name) with geometry_key (and the named instance when
/// instance is not empty), waiting for a starting one; when none, starts executable with args
/// (plus its instance name: instance, else context.instance; heartbeat period and bus_args), waits
/// for READY and returns the process (null when one was already there).
/// @throws std::runtime_error when it cannot be started or is not READY in time (with its log).
std::unique_ptr<StartedService> ensure_service(lcm::LCM& lcm, const bus::HeartbeatMonitor& monitor,
                                               const StartContext& context, const std::string& model,
                                               const std::string& geometry_key, const std::string& executable,
                                               std::vector<std::string> args, const std::string& instance = "");

}  // namespace wrc::cli
