// SPDX-License-Identifier: Apache-2.0
#include "contactd/spline_model_source.hpp"

#include <unistd.h>

#include <iostream>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/clock.hpp"
#include "core/identity/geometry_key.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/spline_model_file.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/progress_t.hpp"

namespace wrc::contactd {

SplineModelSource::SplineModelSource(lcm::LCM& lcm, const bus::ChannelNames& names, std::string sender,
                                     GeometrySpec spec, SplineFitOptions fit, double retry_period)
    : lcm_(lcm), request_channel_(names.name(bus::channel::kGeometryRequest)), stamper_(std::move(sender)),
      spec_(std::move(spec)), fit_(std::move(fit)), retry_period_(retry_period),
      geometry_key_(wrc::geometry_key(spec_)), model_key_(protocol::model_key(geometry_key_, fit_)),
      rejections_(stamper_.sender() + " SPLINE_MODEL listener") {
  if (!(retry_period_ > 0.0)) throw std::invalid_argument("SplineModelSource: retry period must be positive");
  fit_.validate();
  // Request ids unique per process start: pid in the high bits, a counter below.
  request_id_ = (static_cast<std::int64_t>(getpid()) << 20);
  model_subscription_ = std::make_unique<bus::GuardedSubscription<spline_model_t>>(
      lcm_, names.name(bus::channel::kSplineModel), stamper_.sender() + " SPLINE_MODEL listener",
      [this](const spline_model_t& m, const bus::ReceivedMessage& info) { on_model(m, *info.channel); }, 100);
  progress_subscription_ = std::make_unique<bus::GuardedSubscription<progress_t>>(
      lcm_, names.name(bus::channel::kProgress), stamper_.sender() + " PROGRESS listener",
      [this](const progress_t& p, const bus::ReceivedMessage&) { on_progress(p); }, 100);
}

SplineModelSource::~SplineModelSource() = default;

void SplineModelSource::tick() {
  if (!model_hash_.empty() || pending_) return;  // a model came: no more requests
  if (bus::monotonic_seconds() - last_request_ >= retry_period_) send_request();
}

std::shared_ptr<const SplineContactGeometry> SplineModelSource::take() {
  auto out = std::move(pending_);
  pending_.reset();
  return out;
}

void SplineModelSource::send_request() {
  geometry_request_t request;
  stamper_.stamp(request.header);
  request.request_id = ++request_id_;
  request.track = protocol::to_message(spec_);
  request.fit = protocol::to_message(fit_);
  request.recompute = false;
  bus::publish_signed(lcm_, request_channel_, request);
  last_request_ = bus::monotonic_seconds();
  ++requests_sent_;
  if (requests_sent_ == 1 || requests_sent_ % 10 == 0)
    std::cerr << stamper_.sender() << ": asked wrc-geometryd for spline model " << model_key_.substr(0, 12)
              << " (request " << requests_sent_ << ")\n";
}

void SplineModelSource::on_model(const spline_model_t& reference, const std::string& channel) {
  if (reference.model_key != model_key_) return;  // another geometry or other fit options
  if (reference.model_hash == model_hash_) return;  // the model we have, republished
  try {
    const spline_model_t full = protocol::resolve_model(reference);
    pending_ = protocol::decode_model(full);
    model_hash_ = full.model_hash;
  } catch (const std::exception& e) {
    rejections_.reject(channel, std::string("spline model ") + reference.model_key.substr(0, 12) +
                                    " not usable: " + e.what());
  }
}

void SplineModelSource::on_progress(const progress_t& progress) {
  if (progress.request_id != request_id_) return;
  last_progress_ = progress.message;
  if (progress.total > 0) last_progress_ += ", " + std::to_string(100 * progress.done / progress.total) + " %";
  if (progress.message.rfind("rejected: ", 0) != 0) return;
  rejections_.reject(progress_subscription_->channel(), "wrc-geometryd rejected the request: " + progress.message);
}

}  // namespace wrc::contactd
