// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// How wrc-contactd --model spline gets its model: it asks wrc-geometryd (geometry_request_t on
/// GEOMETRY_REQUEST, re-sent every retry period while nothing has come), listens on SPLINE_MODEL
/// for the answer or any later publication of the same model (same model_key: a recompute),
/// reads the model file, checks its SHA-256 and the model hash, and decodes it. A model file it
/// cannot read (wrc-geometryd on another machine) comes in pieces instead (model_piece_t on a
/// reply channel of its own, protocol/geometry/model_pieces.hpp): all asked for at once, the
/// missing ones again while none comes for kPieceRetryPeriod, the whole used only with the file's
/// size and SHA-256. Used from the service's loop thread only.

#include <memory>
#include <optional>
#include <string>

#include <lcm/lcm-cpp.hpp>

#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "bus/transport/rejection_log.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/spline/spline_contact_geometry.hpp"
#include "core/spline/spline_fit_options.hpp"
#include "protocol/geometry/model_pieces.hpp"
#include "wrc/model_piece_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::contactd {

/// [s] silence of the pieces after which the missing ones are asked for again.
inline constexpr double kPieceRetryPeriod = 0.3;

class SplineModelSource {
 public:
  /// Subscribes to SPLINE_MODEL and PROGRESS (names with prefix); sends nothing yet.
  /// @param retry_period [s] between requests while no model has come, > 0.
  SplineModelSource(lcm::LCM& lcm, const bus::ChannelNames& names, std::string sender, GeometrySpec spec,
                    SplineFitOptions fit, double retry_period);
  ~SplineModelSource();
  SplineModelSource(const SplineModelSource&) = delete;
  SplineModelSource& operator=(const SplineModelSource&) = delete;

  /// Sends the request when none was sent yet or the retry period has passed without a model, and
  /// asks again for the missing pieces of a model coming in pieces (also of a recompute, once a
  /// model is in use: call it from the serving loop too).
  void tick();
  /// The model received and checked since the last call, or null.
  std::shared_ptr<const SplineContactGeometry> take();

  const std::string& geometry_key() const { return geometry_key_; }
  const std::string& model_key() const { return model_key_; }
  /// SHA-256 of the data of the model taken last (empty before the first).
  const std::string& model_hash() const { return model_hash_; }
  /// Requests sent so far.
  int requests_sent() const { return requests_sent_; }
  /// Piece requests sent so far (0 when the model file was read) [-].
  int piece_requests_sent() const { return piece_requests_sent_; }
  /// What wrc-geometryd last reported for this service's request (its stage and fraction done;
  /// empty before any report), for the heartbeat's activity.
  const std::string& last_progress() const { return last_progress_; }

 private:
  void on_model(const spline_model_t& reference, const std::string& channel);
  void on_progress(const progress_t& progress);
  void on_piece(const model_piece_t& piece, const std::string& channel);
  void send_request();
  /// Asks wrc-geometryd for the missing pieces (at most MAX_PIECES of them).
  void request_missing_pieces();
  /// "model pieces: N of M received", for the activity.
  std::string pieces_progress() const;

  lcm::LCM& lcm_;
  std::string request_channel_;
  bus::HeaderStamper stamper_;
  GeometrySpec spec_;
  SplineFitOptions fit_;
  double retry_period_;
  std::string geometry_key_;
  std::string model_key_;
  std::string last_progress_;
  std::string model_hash_;
  std::int64_t request_id_ = 0;
  int requests_sent_ = 0;
  double last_request_ = -1e300;  // [s] monotonic
  std::shared_ptr<const SplineContactGeometry> pending_;
  bus::RejectionLog rejections_;
  std::unique_ptr<bus::GuardedSubscription<spline_model_t>> model_subscription_;
  std::unique_ptr<bus::GuardedSubscription<progress_t>> progress_subscription_;
  // A model coming in pieces: its reference, the pieces so far, where they come.
  std::string piece_request_channel_;
  std::string piece_channel_;
  spline_model_t pieced_reference_;
  std::optional<protocol::ModelPieces> pieces_;
  double last_piece_activity_ = -1e300;  // [s] monotonic: the last piece or piece request
  int piece_requests_sent_ = 0;
  std::unique_ptr<bus::GuardedSubscription<model_piece_t>> piece_subscription_;
};

}  // namespace wrc::contactd
