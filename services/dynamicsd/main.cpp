// SPDX-License-Identifier: Apache-2.0
// wrc-dynamicsd: the wheelset dynamics service. On a run_command_t (RUN_COMMAND) it integrates
// the rigid wheelset on straight track with SUNDIALS IDA, asking the selected contact service
// (CONTACT_QUERY.<model>) for every configuration, swaps the model on CONTACT_SELECT at the next
// step boundary, and publishes WHEELSET_STATE, RUN_STATUS, INTEGRATOR_STATS and RUN_SUMMARY.
//
//   wrc-dynamicsd [--instance NAME] [--channel-prefix P] [--lcm-url URL] [--heartbeat-period S]

#include <iostream>

#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/service/service_main.hpp"
#include "bus/service/service_options.hpp"
#include "bus/transport/channels.hpp"
#include "dynamicsd/dynamics_service.hpp"

namespace {

int run(const wrc::bus::ServiceOptions& options, const wrc::bus::NoOwnOptions&) {
  using namespace wrc::bus;
  ShutdownSignal::install();
  const ChannelNames names(options.channel_prefix);
  auto lcm = open_lcm(options.lcm_url, options.bus_key);
  const std::string sender = sender_name("wrc-dynamicsd", options.instance);
  HeartbeatPublisher heartbeat(*lcm, names.name(channel::kHeartbeat),
                               {"wrc-dynamicsd", "dynamicsd", options.instance, names.name(channel::kRunCommand)},
                               options.heartbeat_period);
  heartbeat.publish_now();  // STARTING
  wrc::dynamics::DynamicsService service(*lcm, options.lcm_url, names, options.instance, sender,
                                        [&heartbeat] { heartbeat.tick(); });
  heartbeat.set_activity_source([&service] { return service.activity(); });
  service.set_serving_check([&heartbeat] { return heartbeat.state() != wrc::heartbeat_t::DUPLICATE; });
  ServiceLoop loop(*lcm, heartbeat);
  for (wrc::bus::LaneSocket* lane : service.lanes()) loop.add_inbox(*lane);
  // Whole integrator steps for at most a fifth of a heartbeat period per turn, so that heartbeats
  // and commands keep flowing during a run.
  const double budget = 0.2 * options.heartbeat_period;
  loop.set_idle_hook([&] {
    service.poll(budget);
    loop.set_max_wait(service.running() ? 0.0 : 0.05);
  });
  std::cerr << sender << ": waiting for runs on " << names.name(channel::kRunCommand) << "\n";
  const int rc = loop.run();
  std::cerr << sender << ": stopped (signal " << ShutdownSignal::signal_number() << ")\n";
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  return wrc::bus::service_main<wrc::bus::NoOwnOptions>(
      argc, argv, "wrc-dynamicsd",
      "usage: wrc-dynamicsd [options]\n"
      "Wheelset dynamics (SUNDIALS IDA) with the contact from a contact service: commands on RUN_COMMAND,\n"
      "swaps on CONTACT_SELECT; publishes WHEELSET_STATE, RUN_STATUS, INTEGRATOR_STATS and RUN_SUMMARY.\n",
      run);
}
