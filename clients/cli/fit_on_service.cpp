// SPDX-License-Identifier: Apache-2.0
#include "cli/fit_on_service.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "bus/auth/signed_publish.hpp"
#include "bus/process/shutdown_signal.hpp"
#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "cli/progress_bar.hpp"
#include "cli/service_starter.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/numerics/number_text.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::cli {
namespace {

constexpr double kResendPeriod = 2.0;     // [s] re-send the request while nothing at all is heard of it
constexpr std::size_t kKeyDigits = 12;    // hex digits of a key shown
constexpr int kMaxServiceLosses = 1;      // services lost with the request before the client gives up

// What is known of the process signing with a nonce, from its heartbeats.
enum class Fitter { kUnheard, kAlive, kStopped };

// kStopped when its heartbeats ceased (or it was forgotten after being seen); kUnheard while its
// first heartbeat may still be on its way.
Fitter fitter_state(const bus::HeartbeatMonitor& monitor, std::uint64_t nonce, double now, bool seen_before) {
  for (const bus::ServiceStatus& s : monitor.services(now))
    if (s.nonce == nonce) return s.alive ? Fitter::kAlive : Fitter::kStopped;
  return seen_before ? Fitter::kStopped : Fitter::kUnheard;
}

}  // namespace

std::vector<OptionSpec> fit_on_service_option_specs() {
  return {{"--service", false, "precompute on wrc-geometryd (started when none runs) instead of in this process", ""},
          {"--recompute", false, "with --service: fit again even when the model is in the service's cache", ""},
          {"--wait", true, "with --service: longest wait for the model [s]", "600", NumberRange{1.0, 86400.0}}};
}

int fit_on_service(const Options& o, const GeometrySpec& spec, const SplineFitOptions& fit) {
  const double wait = o.number("--wait");
  const std::string key = geometry_key(spec);
  const std::string model_key = protocol::model_key(key, fit);
  CommandBus session(o, "fit");
  bus::ShutdownSignal::install();
  handle_until(*session.lcm, bus::monotonic_seconds() + kServiceDiscoveryTime, [] { return false; });
  std::unique_ptr<StartedService> started =
      ensure_service(*session.lcm, session.monitor, start_context_from(o, "fit", "f" + std::to_string(::getpid())),
                     "geometryd", "", "wrc-geometryd", {});

  const std::int64_t request_id = static_cast<std::int64_t>(bus::wall_utime());
  ProgressBar bar("fit on wrc-geometryd");
  std::optional<spline_model_t> answer;
  std::string failure;
  bool heard = false;
  std::uint64_t fitter = 0;  // signing nonce of the wrc-geometryd that answered with progress
  bool fitter_seen = false;  // its heartbeats were heard since
  bus::GuardedSubscription<progress_t> progress(
      *session.lcm, session.names.name(bus::channel::kProgress), "fit progress",
      [&](const progress_t& p, const bus::ReceivedMessage& info) {
        if (p.request_id != request_id) return;
        heard = true;
        if (info.origin.nonce != fitter) fitter_seen = false;
        fitter = info.origin.nonce;
        if (p.message.rfind("rejected: ", 0) == 0 || p.message.rfind("failed: ", 0) == 0) failure = p.message;
        else bar.update(p.done, p.total, p.message);
      });
  bus::GuardedSubscription<spline_model_t> models(
      *session.lcm, session.names.name(bus::channel::kSplineModel), "fit answer",
      [&](const spline_model_t& m, const bus::ReceivedMessage&) {
        if (m.request_id == request_id && m.model_key == model_key) answer = m;
      }, 100, 1 << 20);

  geometry_request_t request{};
  bus::HeaderStamper stamper(bus::sender_name("wrc-fit", std::to_string(::getpid())));
  request.request_id = request_id;
  request.track = protocol::to_message(spec);
  request.fit = protocol::to_message(fit);
  request.recompute = o.has("--recompute");
  std::cerr << "fit: asking wrc-geometryd for spline model " << model_key.substr(0, kKeyDigits) << " (geometry key "
            << key.substr(0, kKeyDigits) << (request.recompute ? ", recompute" : "") << ")\n";
  const double deadline = bus::monotonic_seconds() + wait;
  double next_send = 0.0;
  int losses = 0;  // wrc-geometryd processes that stopped while they had this request
  while (!answer && failure.empty()) {
    const double now = bus::monotonic_seconds();
    if (bus::ShutdownSignal::requested()) throw std::runtime_error("interrupted while waiting for the model");
    if (now > deadline)
      throw std::runtime_error("no spline model from wrc-geometryd within --wait " + shortest_number_text(wait) + " s");
    // The service that took the request stopped before answering (its heartbeats ceased): the
    // next one is asked once more; a second loss ends the wait, since the request itself may be
    // what stops them.
    const Fitter state =
        heard && fitter != 0 ? fitter_state(session.monitor, fitter, now, fitter_seen) : Fitter::kUnheard;
    fitter_seen = fitter_seen || state == Fitter::kAlive;
    if (state == Fitter::kStopped) {
      if (++losses > kMaxServiceLosses)
        throw std::runtime_error("wrc-geometryd stopped twice while it had this request; not sending it again (see "
                                 "the service's log: the fit itself may be what stops it)");
      std::cerr << "fit: wrc-geometryd stopped while it had this request; sending it once more\n";
      heard = false;
      fitter = 0;
      fitter_seen = false;
      next_send = now;
    }
    // A request lost on the way is sent again; once the service answers with progress, it is working on it.
    if (!heard && now >= next_send) {
      stamper.stamp(request.header);
      bus::publish_signed(*session.lcm, session.names.name(bus::channel::kGeometryRequest), request);
      next_send = now + kResendPeriod;
    }
    if (session.lcm->handleTimeout(100) < 0 && !bus::ShutdownSignal::requested())
      throw std::runtime_error("LCM failed while waiting for the model");
  }
  bar.finish();
  if (!failure.empty()) throw std::runtime_error("wrc-geometryd: " + failure);
  const spline_model_t& m = *answer;
  std::printf("spline model %s, model hash %s\n", m.model_key.substr(0, kKeyDigits).c_str(),
              m.model_hash.substr(0, kKeyDigits).c_str());
  std::printf("answered in %.3f s; the model's precomputation took %.3f s (sampling %.3f s, fitting %.3f s)\n",
              bus::monotonic_seconds() - (deadline - wait), m.sampling_seconds + m.fitting_seconds, m.sampling_seconds,
              m.fitting_seconds);
  if (m.file_path.empty()) std::printf("model inline in the answer (%d B)\n", m.getEncodedSize());
  else std::printf("model file %s (%lld B, SHA-256 checked by its readers)\n", m.file_path.c_str(), static_cast<long long>(m.file_size));
  if (started) started->stop_and_forget();
  return 0;
}

}  // namespace wrc::cli
