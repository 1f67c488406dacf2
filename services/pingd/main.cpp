// SPDX-License-Identifier: Apache-2.0
// wrc-pingd: the diagnostic service of the wrc bus. It answers every ping_request_t on PING
// (addressed to its instance or to any) with a ping_reply_t echoing request id and payload on
// the request's reply channel, and sends heartbeats (model "pingd"). It has no computation, so
// the round trip to it is the floor of every service latency on the bus.
//
//   wrc-pingd [--instance NAME] [--channel-prefix P] [--lcm-url URL] [--heartbeat-period S]

#include <exception>
#include <iostream>

#include "bus/process/line_atomic_stderr.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/service/service_options.hpp"
#include "bus/service/serving_activity.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/request_server.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace {

constexpr int kMaxPayload = 60000;  // [B] keeps request and reply in one UDP datagram

int run(const wrc::bus::ServiceOptions& options) {
  using namespace wrc::bus;
  ShutdownSignal::install();
  const ChannelNames names(options.channel_prefix);
  auto lcm = open_lcm(options.lcm_url, options.bus_key);
  const std::string request_channel = names.name(channel::kPing);
  const std::string sender = sender_name("wrc-pingd", options.instance);

  HeartbeatPublisher heartbeat(*lcm, names.name(channel::kHeartbeat),
                               {"wrc-pingd", "pingd", options.instance, request_channel},
                               options.heartbeat_period);
  heartbeat.publish_now();  // STARTING

  const std::string instance = options.instance;
  RequestServer<wrc::ping_request_t, wrc::ping_reply_t> server(
      *lcm, request_channel, sender,
      [instance](const wrc::ping_request_t& request, wrc::ping_reply_t& reply) {
        reply.instance = instance;
        reply.status = wrc::ping_reply_t::OK;
        reply.num_payload = request.num_payload;
        reply.payload = request.payload;
      });
  server.set_address_filter([instance](const wrc::ping_request_t& request) {
    return request.instance.empty() || request.instance == instance;
  });
  server.set_validator([](const wrc::ping_request_t& request) -> std::string {
    if (request.num_payload < 0 || request.num_payload > kMaxPayload) {
      return "num_payload " + std::to_string(request.num_payload) + " is outside [0, 60000] bytes";
    }
    return {};
  });
  server.set_error_filler([instance](const wrc::ping_request_t&, RequestError, const std::string& why,
                                     wrc::ping_reply_t& reply) {
    reply.instance = instance;
    reply.status = wrc::ping_reply_t::BAD_REQUEST;
    reply.message = why;
    reply.num_payload = 0;
  });

  heartbeat.set_activity_source(ServingActivity("pings", [&server] { return server.counters().answered; }));
  ServiceLoop loop(*lcm, heartbeat);
  loop.add_load_source(&server);
  std::cerr << sender << ": serving " << request_channel << "\n";
  const int rc = loop.run();
  const auto& c = server.counters();
  std::cerr << sender << ": stopped (signal " << ShutdownSignal::signal_number() << "), answered "
            << c.answered << ", rejected " << c.rejected << "\n";
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  wrc::bus::make_stderr_line_atomic();  // one log shared with other processes: whole lines only
  try {
    const auto options = wrc::bus::ServiceOptions::parse(argc, argv);
    if (options.help) {
      std::cout << "usage: wrc-pingd [options]\n"
                   "Diagnostic service: answers ping requests on PING and sends heartbeats.\n\n"
                << wrc::bus::ServiceOptions::help_text();
      return 0;
    }
    if (!options.rest.empty()) {
      std::cerr << "wrc-pingd: unknown argument '" << options.rest.front() << "' (see --help)\n";
      return 2;
    }
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "wrc-pingd: " << e.what() << "\n";
    return 1;
  }
}
