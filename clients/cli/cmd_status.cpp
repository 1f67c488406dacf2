// SPDX-License-Identifier: Apache-2.0
// wrc status: lists the service processes on the bus from their heartbeats, with the first 12 hex
// digits of the geometry key and of the model hash each computes with ("-" when none) and the
// messages each dropped (unsigned/bad signature/replayed/malformed), and below it what the process
// is doing (its heartbeat's activity: the run and its simulated time, the fit and its stage, the
// query rate, what a service waits for). Two processes claiming one model and instance name show
// as two lines, the newer one DUPLICATE with its reason.

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/drop_counters.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"

namespace wrc::cli {
namespace {

constexpr std::size_t kHashPrefix = 12;  // hex digits shown of a geometry key or model hash

// The first kHashPrefix hex digits of a SHA-256, "-" when there is none.
std::string short_hash(const std::string& hash) { return hash.empty() ? "-" : hash.substr(0, kHashPrefix); }

const char* state_name(std::int8_t state) {
  switch (state) {
    case wrc::heartbeat_t::STARTING: return "STARTING";
    case wrc::heartbeat_t::READY: return "READY";
    case wrc::heartbeat_t::DRAINING: return "DRAINING";
    case wrc::heartbeat_t::DUPLICATE: return "DUPLICATE";
    default: return "UNKNOWN";
  }
}

int run_status(const std::vector<std::string>& args) {
  Options options("status", "[options]",
                  {{"--duration", true, "how long to listen for heartbeats [s]", "1.5", NumberRange{0.05, 3600.0}},
                   {"--channel-prefix", true, "channel prefix of the simulation", "none"},
                   {"--lcm-url", true, "LCM URL", "LCM's default"},
                   {"--bus-key", true, "bus key file", "$WRC_BUS_KEY, else ~/.config/wrc/bus.key"},
                   {"--all", false, "also list services whose heartbeats stopped while listening", ""},
                   {"--format", true, "table or csv", "table"}},
                  args);
  if (options.help_requested()) {
    std::cout << options.help() << "\nOne line per live service: model, instance, pid, state, load, the\n"
                                   "first 12 hex digits of its geometry key and model hash (- when none)\n"
                                   "messages it dropped (DROPPED u/s/r/m: unsigned, bad signature, replayed\n"
                                   "or stale, malformed) and its request channel; a DUPLICATE line is followed\n"
                                   "by why it refuses to serve. Below each line, what the process is doing\n"
                                   "(\"doing: run r1: spline, t = 0.84 of 2 s, ...\", \"fitting ...\", a query rate).\n";
    return 0;
  }
  const double duration = options.number("--duration");
  const std::string format = options.choice("--format", {"table", "csv"});
  const bus::ChannelNames names(options.text("--channel-prefix"));
  auto lcm = bus::open_lcm(options.text("--lcm-url"), options.text("--bus-key"));
  bus::HeartbeatMonitor monitor(*lcm, names.name(bus::channel::kHeartbeat));
  const double end = bus::monotonic_seconds() + duration;
  for (double left = duration; left > 0.0; left = end - bus::monotonic_seconds()) {
    lcm->handleTimeout(static_cast<int>(std::ceil(left * 1e3)));
  }
  const double now = bus::monotonic_seconds();
  std::ostringstream out;
  if (format == "csv") {
    out << "model,instance,pid,state,alive,version,uptime,handled,rejected,latency_p95,geometry_key,model_hash,"
           "dropped_unsigned,dropped_bad_signature,dropped_replayed,dropped_malformed,state_reason,request_channel,"
           "activity\n";
  } else {
    out << std::left << std::setw(12) << "MODEL" << std::setw(10) << "INSTANCE" << std::setw(8) << "PID"
        << std::setw(10) << "STATE" << std::setw(10) << "UPTIME[s]" << std::setw(10) << "HANDLED"
        << std::setw(9) << "REJECTED" << std::setw(14) << "P95[s]" << std::setw(14) << "GEOMETRY" << std::setw(14)
        << "MODEL-HASH" << std::setw(14) << "DROPPED" << "CHANNEL\n";
  }
  int shown = 0;
  for (const auto& s : monitor.services(now)) {
    if (!s.alive && !options.has("--all")) continue;
    ++shown;
    const auto& hb = s.last;
    std::string state = state_name(hb.state);
    if (!s.alive) state = "DEAD";
    if (hb.interface_version != wrc::heartbeat_t::INTERFACE_VERSION) state += "(v" + std::to_string(hb.interface_version) + "!)";
    if (format == "csv") {
      out << hb.model << "," << hb.instance << "," << hb.pid << "," << state << "," << (s.alive ? 1 : 0)
          << "," << hb.interface_version << "," << hb.uptime << "," << hb.requests_handled << ","
          << hb.requests_rejected << "," << hb.latency_p95 << "," << short_hash(hb.geometry_key) << ","
          << short_hash(hb.model_hash) << "," << hb.dropped_unsigned << "," << hb.dropped_bad_signature << ","
          << hb.dropped_replayed << "," << hb.dropped_malformed << ",\"" << hb.state_reason << "\","
          << hb.request_channel << ",\"" << hb.activity << "\"\n";
    } else {
      std::ostringstream uptime;
      uptime << std::fixed << std::setprecision(1) << hb.uptime;
      out << std::left << std::setw(12) << hb.model << std::setw(10) << hb.instance << std::setw(8) << hb.pid
          << std::setw(10) << state << std::setw(10) << uptime.str() << std::setw(10) << hb.requests_handled
          << std::setw(9) << hb.requests_rejected << std::setw(14) << hb.latency_p95 << std::setw(14)
          << short_hash(hb.geometry_key) << std::setw(14) << short_hash(hb.model_hash) << std::setw(14)
          << (std::to_string(hb.dropped_unsigned) + "/" + std::to_string(hb.dropped_bad_signature) + "/" +
              std::to_string(hb.dropped_replayed) + "/" + std::to_string(hb.dropped_malformed))
          << hb.request_channel << "\n";
      if (!hb.activity.empty()) out << "  doing: " << hb.activity << "\n";
      if (!hb.state_reason.empty()) out << "  " << state << ": " << hb.state_reason << "\n";
    }
  }
  std::cout << out.str();
  if (shown == 0) std::cerr << "status: no live service heard within " << duration << " s\n";
  if (monitor.rejected() > 0) {
    const bus::DropCounts drops = bus::drop_counts();
    std::cerr << "status: dropped " << monitor.rejected() << " heartbeats here (" << drops.unsigned_messages()
              << " unsigned, " << drops.bad_signature() << " bad signature, " << drops.replayed()
              << " replayed or stale, " << drops.malformed() << " malformed)\n";
  }
  return 0;
}

const CommandRegistrar registrar{{"status", "list the live services from their heartbeats", run_status}};

}  // namespace
}  // namespace wrc::cli
