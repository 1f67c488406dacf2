// SPDX-License-Identifier: Apache-2.0
// wrc-contactd: one contact model (onepoint, interp, multipoint or spline) as a service on the wrc
// bus. It builds the wheelset geometry and the model (heartbeat state STARTING meanwhile, the
// build time in its log; the spline model's data come from wrc-geometryd:
// contactd/spline_model_source.hpp), then answers every contact_query_t on CONTACT_QUERY.<model> addressed to its
// instance (or to any instance while it is the model's leader: contactd/instance_filter.hpp) with
// a contact_reply_t on the query's reply channel, request id echoed. Heartbeats: model, instance,
// state (STARTING, READY, DRAINING on SIGTERM/SIGINT), geometry key (core/identity/geometry_key.hpp;
// the spline model fitted with options other than the default: its model key,
// protocol/contact/contact_service_key.hpp),
// model hash (contactd/model_hash.hpp, once built), and the load (queries handled and rejected,
// handling time mean/p95/max). Replies carry the same key and hash; a query whose non-empty
// geometry_key differs is rejected. The service adds nothing to the model:
// protocol/contact/contact_query_codec.hpp only translates.
//
//   wrc-contactd --model onepoint|interp|multipoint|spline [--wheel W --rail R --rail-cant C --gauge G ...]
//                [--instance NAME] [--channel-prefix P] [--lcm-url URL] [--heartbeat-period S]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <future>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "bus/process/line_atomic_stderr.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_publisher.hpp"
#include "bus/service/percentile.hpp"
#include "bus/service/service_load.hpp"
#include "bus/service/service_loop.hpp"
#include "bus/service/service_main.hpp"
#include "bus/service/service_options.hpp"
#include "bus/service/serving_activity.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/lane_socket.hpp"
#include "bus/transport/lcm_url.hpp"
#include "bus/transport/request_server.hpp"
#include "contactd/contactd_options.hpp"
#include "contactd/instance_filter.hpp"
#include "contactd/model_hash.hpp"
#include "contactd/query_evaluation.hpp"
#include "contactd/spline_model_source.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/identity/geometry_key.hpp"
#include "protocol/contact/contact_service_key.hpp"
#include "core/models/contact_model_factory.hpp"
#include "protocol/contact/contact_lane.hpp"
#include "protocol/contact/contact_query_codec.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace {

/// [s] between requests to wrc-geometryd while the spline service waits for its model.
constexpr double kModelRequestPeriod = 2.0;

/// The geometry and model a service computes with, and what building them cost.
struct Built {
  std::shared_ptr<const wrc::WheelsetGeometry> geometry;
  std::unique_ptr<const wrc::ContactModel> model;
  std::string model_hash;  // SHA-256 of the model's precomputed data; empty if it has none
  double geometry_seconds = 0.0;
  double model_seconds = 0.0;
};

Built build(const wrc::contactd::ContactdOptions& options) {
  Built out;
  const double t0 = wrc::bus::monotonic_seconds();
  out.geometry = std::make_shared<const wrc::WheelsetGeometry>(wrc::make_geometry(options.geometry));
  const double t1 = wrc::bus::monotonic_seconds();
  out.model = wrc::make_contact_model(options.model, out.geometry, wrc::ContactModelOptions{});
  out.model_hash = wrc::contactd::model_hash(*out.model);
  out.geometry_seconds = t1 - t0;
  out.model_seconds = wrc::bus::monotonic_seconds() - t1;
  return out;
}

/// The log line on the compute times of the recent queries (the heartbeat has mean, p95 and max).
std::string compute_time_summary(const wrc::bus::LatencyWindow& times) {
  const std::vector<double>& s = times.samples();
  if (s.empty()) return "no queries";
  const double mean = std::accumulate(s.begin(), s.end(), 0.0) / s.size();
  char buf[160];
  std::snprintf(buf, sizeof buf, "compute time over the last %zu queries: mean %.1f us, p50 %.1f us, p99 %.1f us",
                s.size(), 1e6 * mean, 1e6 * wrc::bus::percentile(s, 0.5), 1e6 * wrc::bus::percentile(s, 0.99));
  return buf;
}

/// What the service computes with: the model (replaced, loop thread only, when a new spline model
/// comes), its hash, and for the spline model the geometry and the source of its data.
struct ServedModel {
  std::string name;
  std::shared_ptr<const wrc::ContactModel> model;
  std::string model_hash;
  std::shared_ptr<const wrc::WheelsetGeometry> geometry;
  std::unique_ptr<wrc::contactd::SplineModelSource> splines;

  /// Builds the spline model from newly received splines and publishes its hash.
  void adopt(std::shared_ptr<const wrc::SplineContactGeometry> fitted, wrc::bus::HeartbeatPublisher& heartbeat) {
    model = wrc::make_contact_model(name, geometry, wrc::ContactModelOptions{}, {std::move(fitted)});
    model_hash = wrc::contactd::model_hash(*model);
    heartbeat.set_model_hash(model_hash);
  }
};

/// The exit code of a service that ends before it serves; nothing when it goes on.
using EarlyExit = std::optional<int>;

/// A model built from the profiles alone, in a worker thread so that STARTING heartbeats keep
/// coming while it is built (the interpolated model takes a while); LCM is only used from this
/// thread. A signal meanwhile ends the process at once.
EarlyExit build_model(const wrc::contactd::ContactdOptions& options, const std::string& sender, const std::string& key,
                      wrc::bus::HeartbeatPublisher& heartbeat, std::function<std::string()>& activity,
                      ServedModel& served) {
  using wrc::bus::ShutdownSignal;
  std::cerr << sender << ": building the " << served.name << " model (wheel " << options.geometry.wheel << ", rail "
            << options.geometry.rail << ", geometry key " << key << ")\n";
  activity = [&served] { return "building the " + served.name + " model"; };
  auto pending = std::async(std::launch::async, build, std::cref(options));
  while (pending.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
    if (ShutdownSignal::requested()) {
      heartbeat.set_state(wrc::heartbeat_t::DRAINING);
      std::cerr << sender << ": signal " << ShutdownSignal::signal_number()
                << " while building the model; exiting without waiting for it\n";
      std::cerr.flush();
      std::_Exit(0);  // the build thread cannot be interrupted; nothing else needs cleaning up
    }
    heartbeat.tick();
  }
  Built built;
  try {
    built = pending.get();
  } catch (const std::exception& e) {
    heartbeat.set_state(wrc::heartbeat_t::DRAINING);
    std::cerr << sender << ": cannot build the " << served.name << " model: " << e.what() << "\n";
    return 1;
  }
  std::cerr << sender << ": built the " << served.name << " model in " << built.model_seconds << " s (geometry "
            << built.geometry_seconds << " s)"
            << (built.model_hash.empty() ? std::string() : ", model hash " + built.model_hash) << "\n";
  served.model = std::move(built.model);
  served.model_hash = built.model_hash;
  return std::nullopt;
}

/// A model whose data come from wrc-geometryd: asked for, and waited for (STARTING) until here.
EarlyExit wait_for_spline_model(lcm::LCM& lcm, const wrc::bus::ChannelNames& names,
                                const wrc::contactd::ContactdOptions& options, const std::string& sender,
                                const std::string& key, wrc::bus::HeartbeatPublisher& heartbeat,
                                std::function<std::string()>& activity, ServedModel& served) {
  using wrc::bus::ShutdownSignal;
  try {
    served.geometry = std::make_shared<const wrc::WheelsetGeometry>(wrc::make_geometry(options.geometry));
  } catch (const std::exception& e) {
    heartbeat.set_state(wrc::heartbeat_t::DRAINING);
    std::cerr << sender << ": cannot build the geometry: " << e.what() << "\n";
    return 1;
  }
  served.splines = std::make_unique<wrc::contactd::SplineModelSource>(lcm, names, sender, options.geometry,
                                                                      options.fit, kModelRequestPeriod);
  wrc::contactd::SplineModelSource& splines = *served.splines;
  activity = [&splines] {
    const std::string& p = splines.last_progress();
    return "waiting for spline model " + splines.model_key().substr(0, 12) + " from wrc-geometryd" +
           (p.empty() ? std::string() : " (" + p + ")");
  };
  std::cerr << sender << ": waiting for spline model " << splines.model_key().substr(0, 12)
            << " from wrc-geometryd (geometry key " << key << ")\n";
  while (!served.model) {
    if (ShutdownSignal::requested()) {
      heartbeat.set_state(wrc::heartbeat_t::DRAINING);
      std::cerr << sender << ": signal " << ShutdownSignal::signal_number() << " while waiting for the model\n";
      return 0;
    }
    splines.tick();
    if (lcm.handleTimeout(20) < 0) {
      std::cerr << sender << ": LCM failed while waiting for the model\n";
      return 1;
    }
    heartbeat.tick();
    if (auto fitted = splines.take()) {
      served.adopt(std::move(fitted), heartbeat);
      std::cerr << sender << ": got spline model " << splines.model_key().substr(0, 12) << ", model hash "
                << served.model_hash << " after " << splines.requests_sent() << " request(s)\n";
    }
  }
  return std::nullopt;
}

using ContactServer = wrc::bus::RequestServer<wrc::contact_query_t, wrc::contact_reply_t>;

/// The checks of a query before it is computed (this service's model and geometry key, then the
/// protocol's rules), and the error reply for one that fails them.
void set_query_checks(ContactServer& server, const ServedModel& served, const std::string& instance,
                      const std::string& key) {
  using wrc::contact_query_t;
  using wrc::contact_reply_t;
  server.set_validator([&served, key](const contact_query_t& query) -> std::string {
    if (!query.model.empty() && query.model != served.name) {
      return "model = '" + query.model + "' but this service runs '" + served.name + "'";
    }
    if (!query.geometry_key.empty() && query.geometry_key != key) {
      return "geometry_key = '" + query.geometry_key + "' but this service computes with geometry_key " + key;
    }
    return wrc::protocol::validate_query(query);
  });
  server.set_error_filler([&served, instance, key](const contact_query_t&, wrc::bus::RequestError error,
                                                   const std::string& why, contact_reply_t& reply) {
    reply.model = served.name;
    reply.instance = instance;
    reply.geometry_key = key;
    reply.model_hash = served.model_hash;
    reply.status = error == wrc::bus::RequestError::kBadRequest ? contact_reply_t::BAD_REQUEST
                                                                : contact_reply_t::INTERNAL_ERROR;
    reply.message = why;
    reply.num_configurations = 0;
    reply.results.clear();
  });
}

int run(const wrc::bus::ServiceOptions& service, const wrc::contactd::ContactdOptions& options) {
  using namespace wrc::bus;
  using wrc::contact_query_t;
  using wrc::contact_reply_t;
  ShutdownSignal::install();
  const ChannelNames names(service.channel_prefix);
  auto lcm = open_lcm(service.lcm_url, service.bus_key);
  const std::string request_channel = names.name(channel::kContactQuery, options.model);
  const std::string sender = sender_name("wrc-contactd", service.instance);
  const std::string instance = service.instance;
  const std::string key = wrc::protocol::contact_service_key(options.model, options.geometry, options.fit);
  ServedModel served;
  served.name = options.model;

  HeartbeatPublisher heartbeat(*lcm, names.name(channel::kHeartbeat),
                               {"wrc-contactd", served.name, instance, request_channel}, service.heartbeat_period);
  heartbeat.set_geometry_key(key);
  // What the process does, for `wrc status`: each phase below replaces it.
  std::function<std::string()> activity = [] { return "starting"; };
  heartbeat.set_activity_source([&activity] { return activity(); });
  heartbeat.publish_now();  // STARTING

  const EarlyExit early = wrc::contact_model_entry(served.name).needs_data
                              ? wait_for_spline_model(*lcm, names, options, sender, key, heartbeat, activity, served)
                              : build_model(options, sender, key, heartbeat, activity, served);
  if (early) return *early;
  heartbeat.set_model_hash(served.model_hash);

  LatencyWindow compute_times;  // recent evaluation times [s], for the log
  wrc::contactd::InstanceFilter filter(*lcm, names.name(channel::kHeartbeat), served.name, instance);
  const ContactServer::Handler answer = [&](const contact_query_t& query, contact_reply_t& reply) {
    const double t0 = monotonic_seconds();
    reply.model = served.name;
    reply.instance = instance;
    reply.geometry_key = key;
    reply.model_hash = served.model_hash;
    wrc::contactd::evaluate_query(*served.model, query, reply);
    reply.compute_time = monotonic_seconds() - t0;
    compute_times.add(reply.compute_time);
  };
  // The same queries are answered on the bus (wrc query, lcm-spy users, any client) and on the
  // model's query lane, where the dynamics asks, with the replies on its reply lane
  // (protocol/contact/contact_lane.hpp).
  const std::string bus_url = effective_lcm_url(service.lcm_url);
  const std::string lane_url = lane_lcm_url(bus_url, wrc::protocol::contact_query_lane(served.name));
  // The query lane is read from a socket in this thread (bus/transport/lane_socket.hpp): the
  // kernel wakes the service itself, with no LCM receive thread in between.
  std::unique_ptr<LaneSocket> lane = lane_url.empty() ? nullptr : std::make_unique<LaneSocket>(lane_url);
  std::unique_ptr<lcm::LCM> reply_lane =
      lane_url.empty() ? nullptr : open_lcm(lane_lcm_url(bus_url, wrc::protocol::contact_reply_lane(served.name)));
  std::vector<std::unique_ptr<ContactServer>> servers;
  servers.push_back(std::make_unique<ContactServer>(*lcm, request_channel, sender, answer));
  if (lane) {
    servers.push_back(std::make_unique<ContactServer>(*lane, request_channel, sender, answer));
    servers.back()->reply_on(*reply_lane);
  }
  for (const auto& server : servers) {
    server->set_address_filter([&filter](const contact_query_t& query) { return filter.answers(query); });
    set_query_checks(*server, served, instance, key);
  }
  const auto counted = [&servers](auto field) {
    std::int64_t sum = 0;
    for (const auto& server : servers) sum += server->counters().*field;
    return sum;
  };
  activity = ServingActivity(served.name + " queries", [&counted] { return counted(&ServerCounters::answered); });
  ServiceLoop loop(*lcm, heartbeat);
  if (lane) loop.add_inbox(*lane);
  for (const auto& server : servers) loop.add_load_source(server.get());
  if (served.splines) {
    // A recompute of the same model (same model_key, new data) replaces the model between queries.
    loop.set_idle_hook([&] {
      served.splines->tick();  // the missing pieces of a recompute coming in pieces
      auto fitted = served.splines->take();
      if (!fitted) return;
      served.adopt(std::move(fitted), heartbeat);
      std::cerr << sender << ": replaced the spline model, model hash now " << served.model_hash << "\n";
    });
  }
  std::cerr << sender << ": serving " << request_channel << (lane ? " (also on its lane " + lane_url + ")" : "") << "\n";
  const int rc = loop.run();
  std::cerr << sender << ": stopped (signal " << ShutdownSignal::signal_number() << "), answered "
            << counted(&ServerCounters::answered) << ", rejected " << counted(&ServerCounters::rejected)
            << ", for other instances " << counted(&ServerCounters::not_addressed) << "; "
            << compute_time_summary(compute_times) << "\n";
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  return wrc::bus::service_main<wrc::contactd::ContactdOptions>(
      argc, argv, "wrc-contactd",
      "usage: wrc-contactd --model onepoint|interp|multipoint|spline [options]\n"
      "Contact service: answers contact_query_t on CONTACT_QUERY.<model> with contact_reply_t.\n",
      run);
}
