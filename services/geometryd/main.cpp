// SPDX-License-Identifier: Apache-2.0
// wrc-geometryd: the geometry precomputation service of the wrc bus. It answers every
// geometry_request_t on GEOMETRY_REQUEST with the spline contact model (spline_model_t, request
// id echoed) on the request's reply channel or SPLINE_MODEL: from its model cache
// (<cache-dir>/<model_key>.splinemodel) when the model was fitted before, otherwise after fitting
// it (core/spline/spline_geometry_fit.hpp) in one worker thread, with progress_t on PROGRESS
// meanwhile. The fit runs off the service loop, so heartbeats (model "geometryd", READY) keep
// coming while it works; LCM is only used from the loop's thread (geometryd/geometry_service.hpp
// has the rules, geometryd/fit_worker.hpp the worker).
//
//   wrc-geometryd [--cache-dir DIR] [--instance NAME] [--channel-prefix P] [--lcm-url URL]
//                 [--heartbeat-period S]

#include <cstdlib>
#include <exception>
#include <iostream>

#include "bus/process/line_atomic_stderr.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/service/service_main.hpp"
#include "bus/service/service_options.hpp"
#include "bus/transport/channels.hpp"
#include "geometryd/fit_worker.hpp"
#include "geometryd/geometry_service.hpp"
#include "geometryd/geometryd_options.hpp"
#include "geometryd/model_cache.hpp"
#include "geometryd/model_piece_server.hpp"

namespace {

constexpr double kProgressInterval = 0.2;  // [s] least time between two progress_t of one fit
constexpr double kLoopWait = 0.05;         // [s] longest LCM wait: how late worker events are published

int run(const wrc::bus::ServiceOptions& service, const wrc::geometryd::GeometrydOptions& options) {
  using namespace wrc::bus;
  ShutdownSignal::install();
  const ChannelNames names(service.channel_prefix);
  const wrc::geometryd::ModelCache cache(options.cache_dir);
  auto lcm = open_lcm(service.lcm_url, service.bus_key);
  const std::string sender = sender_name("wrc-geometryd", service.instance);

  wrc::geometryd::FitWorker worker(kProgressInterval);
  wrc::geometryd::GeometryService server(*lcm, names, sender, cache, worker);
  wrc::geometryd::ModelPieceServer pieces(*lcm, names, sender, cache);  // for spline services on other machines
  HeartbeatPublisher heartbeat(*lcm, names.name(channel::kHeartbeat),
                               {"wrc-geometryd", "geometryd", service.instance, server.request_channel()},
                               service.heartbeat_period);
  heartbeat.publish_now();  // STARTING

  heartbeat.set_activity_source([&server] { return server.activity(); });
  ServiceLoop loop(*lcm, heartbeat);
  loop.add_load_source(&server);
  loop.set_idle_hook([&server] { server.poll(); });
  loop.set_max_wait(kLoopWait);
  std::cerr << sender << ": serving " << server.request_channel() << ", model cache " << cache.dir() << "\n";
  const int rc = loop.run();
  const auto& c = server.counters();
  std::cerr << sender << ": stopped (signal " << ShutdownSignal::signal_number() << "), answered " << c.answered
            << " (from the cache " << c.from_cache << ", waited for a running fit " << c.joined << "), fits "
            << c.fits << ", failed " << c.failed << ", rejected " << server.rejected() << "; model pieces sent "
            << pieces.pieces_sent() << ", piece requests refused " << pieces.refused() << "\n";
  if (worker.stop()) {
    std::cerr << sender << ": a fit is still running; exiting without waiting for it\n";
    std::cerr.flush();
    std::_Exit(rc);  // the fit cannot be interrupted; nothing else needs cleaning up
  }
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  return wrc::bus::service_main<wrc::geometryd::GeometrydOptions>(
      argc, argv, "wrc-geometryd",
      "usage: wrc-geometryd [options]\n"
      "Geometry service: answers geometry_request_t on GEOMETRY_REQUEST with the spline contact\n"
      "model (spline_model_t), fitted or from its cache, and progress_t on PROGRESS.\n",
      run);
}
