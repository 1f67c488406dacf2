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
#include "bus/transport/request_client.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/model_piece_request_t.hpp"
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
  piece_request_channel_ = names.name(bus::channel::kModelPieceRequest);
  piece_channel_ = names.name(bus::channel::kModelPiece, bus::make_client_id("spline"));
  piece_subscription_ = std::make_unique<bus::GuardedSubscription<model_piece_t>>(
      lcm_, piece_channel_, stamper_.sender() + " MODEL_PIECE listener",
      [this](const model_piece_t& p, const bus::ReceivedMessage& info) { on_piece(p, *info.channel); },
      model_piece_request_t::MAX_PIECES);
}

SplineModelSource::~SplineModelSource() = default;

void SplineModelSource::tick() {
  const double now = bus::monotonic_seconds();
  // Pieces are asked for again also once a model is in use: a recompute may come in pieces.
  if (pieces_ && now - last_piece_activity_ >= kPieceRetryPeriod) request_missing_pieces();
  if (!model_hash_.empty() || pending_) return;  // a model came: no more requests
  if (now - last_request_ >= retry_period_) send_request();
}

std::string SplineModelSource::pieces_progress() const {
  return "model pieces: " + std::to_string(pieces_->received()) + " of " + std::to_string(pieces_->count()) +
         " received";
}

void SplineModelSource::request_missing_pieces() {
  model_piece_request_t request{};
  stamper_.stamp(request.header);
  request.model_key = pieces_->model_key();
  request.file_hash = pieces_->file_hash();
  request.reply_channel = piece_channel_;
  request.pieces = pieces_->missing(model_piece_request_t::MAX_PIECES);
  request.num_pieces = static_cast<std::int32_t>(request.pieces.size());
  if (request.num_pieces == 0) return;
  bus::publish_signed(lcm_, piece_request_channel_, request);
  last_piece_activity_ = bus::monotonic_seconds();
  ++piece_requests_sent_;
  last_progress_ = pieces_progress();
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
    pieces_.reset();
    return;
  } catch (const std::exception& e) {
    if (reference.file_path.empty()) {
      rejections_.reject(channel, std::string("spline model ") + reference.model_key.substr(0, 12) +
                                      " not usable: " + e.what());
      return;
    }
    if (pieces_ && pieces_->file_hash() == reference.file_hash) return;  // already coming in pieces
    std::cerr << stamper_.sender() << ": cannot read the file of spline model " << reference.model_key.substr(0, 12)
              << " (" << e.what() << "); asking wrc-geometryd for it in pieces\n";
  }
  try {
    pieces_.emplace(reference);
  } catch (const std::exception& e) {
    rejections_.reject(channel, std::string("spline model ") + reference.model_key.substr(0, 12) + ": " + e.what());
    return;
  }
  pieced_reference_ = reference;
  request_missing_pieces();
}

void SplineModelSource::on_piece(const model_piece_t& piece, const std::string& channel) {
  if (!pieces_ || !pieces_->names_this_file(piece)) return;  // nothing coming, or an earlier file's
  last_piece_activity_ = bus::monotonic_seconds();
  if (const auto why = pieces_->add(piece)) {
    rejections_.reject(channel, "model piece refused: " + *why);
    return;
  }
  last_progress_ = pieces_progress();
  if (!pieces_->complete()) return;
  try {
    const std::vector<char> bytes = pieces_->take_file();
    const spline_model_t full = protocol::model_from_file_bytes(pieced_reference_, bytes, "from pieces");
    pending_ = protocol::decode_model(full);
    model_hash_ = full.model_hash;
    std::cerr << stamper_.sender() << ": spline model " << model_key_.substr(0, 12) << " came in "
              << pieces_->count() << " pieces (" << bytes.size() << " B, SHA-256 checked) after "
              << piece_requests_sent_ << " piece request(s)\n";
    pieces_.reset();
  } catch (const std::exception& e) {
    // A corrupt piece: all are asked for again (take_file forgot them). A whole that does not
    // decode: the file itself is bad, so nothing is asked for until another reference comes.
    rejections_.reject(channel, std::string("spline model ") + model_key_.substr(0, 12) + " from pieces: " + e.what());
    if (pieces_->complete()) pieces_.reset();
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
