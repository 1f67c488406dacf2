// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// wrc-geometryd's answer to model_piece_request_t on MODEL_PIECE_REQUEST: the pieces asked for of
/// a cached model file (protocol/geometry/model_pieces.hpp), one model_piece_t each, on the
/// request's reply channel (default MODEL_PIECE), for a spline service that cannot read the cache
/// (another machine). A request naming a model that is not cached, or whose file now has another
/// SHA-256, is refused and logged (rate-limited); at most kMaxPiecesPerSecond pieces go out per
/// second in all, a request beyond that is refused until the budget refills (its sender asks again).
/// Used from the service's loop thread only.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "bus/transport/rejection_log.hpp"
#include "geometryd/model_cache.hpp"
#include "wrc/model_piece_request_t.hpp"

namespace wrc::geometryd {

/// [1/s] pieces sent per second at most (32 kB each: 16 MB/s), and the burst allowed.
inline constexpr double kMaxPiecesPerSecond = 512.0;

class ModelPieceServer {
 public:
  /// Subscribes to MODEL_PIECE_REQUEST (with the names' prefix); files come from cache.
  ModelPieceServer(lcm::LCM& lcm, const bus::ChannelNames& names, std::string sender, const ModelCache& cache);
  ~ModelPieceServer();
  ModelPieceServer(const ModelPieceServer&) = delete;
  ModelPieceServer& operator=(const ModelPieceServer&) = delete;

  /// Pieces sent so far [-].
  long pieces_sent() const { return pieces_sent_; }
  /// Requests refused so far (malformed, unknown or changed file, over the budget) [-].
  std::int64_t refused() const { return rejections_.count(); }

 private:
  void on_request(const model_piece_request_t& request, const std::string& channel);
  /// The bytes of model_key's cache file (the last file read is kept for its next request; a
  /// request naming another SHA-256 reads it again, for a recompute rewrites the file).
  const std::vector<char>& file_bytes(const std::string& model_key);

  lcm::LCM& lcm_;
  const bus::ChannelNames& names_;
  bus::HeaderStamper stamper_;
  const ModelCache& cache_;
  bus::RejectionLog rejections_;
  std::string file_key_;  // model key of the file in file_ (empty: none)
  std::vector<char> file_;
  std::string file_hash_;
  double budget_ = kMaxPiecesPerSecond;  // [-] pieces that may go out now
  double budget_time_ = 0.0;             // [s] monotonic time the budget was last refilled
  long pieces_sent_ = 0;
  std::unique_ptr<bus::GuardedSubscription<model_piece_request_t>> subscription_;
};

}  // namespace wrc::geometryd
