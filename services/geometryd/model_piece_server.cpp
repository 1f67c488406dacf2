// SPDX-License-Identifier: Apache-2.0
#include "geometryd/model_piece_server.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/clock.hpp"
#include "core/identity/sha256.hpp"
#include "protocol/geometry/message_file.hpp"
#include "protocol/geometry/model_pieces.hpp"

namespace wrc::geometryd {
namespace {

// A model key names a cache file: 64 lower-case hex digits, nothing else (no path in it).
bool is_model_key(const std::string& key) {
  return key.size() == 64 &&
         std::all_of(key.begin(), key.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) ||
                                                                 (c >= 'a' && c <= 'f'); });
}

}  // namespace

ModelPieceServer::ModelPieceServer(lcm::LCM& lcm, const bus::ChannelNames& names, std::string sender,
                                   const ModelCache& cache)
    : lcm_(lcm), names_(names), stamper_(std::move(sender)), cache_(cache),
      rejections_(stamper_.sender() + " MODEL_PIECE_REQUEST server"), budget_time_(bus::monotonic_seconds()) {
  subscription_ = std::make_unique<bus::GuardedSubscription<model_piece_request_t>>(
      lcm_, names_.name(bus::channel::kModelPieceRequest), stamper_.sender() + " MODEL_PIECE_REQUEST server",
      [this](const model_piece_request_t& r, const bus::ReceivedMessage& info) { on_request(r, *info.channel); });
}

ModelPieceServer::~ModelPieceServer() = default;

const std::vector<char>& ModelPieceServer::file_bytes(const std::string& model_key) {
  if (file_key_ != model_key) {
    file_key_.clear();
    file_ = protocol::read_message_file_bytes(cache_.path(model_key), "spline model file");
    file_hash_ = sha256_hex(file_.data(), file_.size());
    file_key_ = model_key;
  }
  return file_;
}

void ModelPieceServer::on_request(const model_piece_request_t& request, const std::string& channel) {
  if (const auto why = protocol::piece_request_violation(request)) {
    rejections_.reject(channel, *why);
    return;
  }
  if (!is_model_key(request.model_key)) {
    rejections_.reject(channel, "model_key is not 64 lower-case hex digits");
    return;
  }
  const double now = bus::monotonic_seconds();
  budget_ = std::min(kMaxPiecesPerSecond, budget_ + (now - budget_time_) * kMaxPiecesPerSecond);
  budget_time_ = now;
  if (budget_ < request.num_pieces) {
    rejections_.reject(channel, "over the budget of " + std::to_string(static_cast<int>(kMaxPiecesPerSecond)) +
                                    " pieces per second: " + std::to_string(request.num_pieces) + " asked for");
    return;
  }
  const std::vector<char>* bytes = nullptr;
  try {
    bytes = &file_bytes(request.model_key);
    if (file_hash_ != request.file_hash) {  // the file kept may have been fitted again since: read it anew
      file_key_.clear();
      bytes = &file_bytes(request.model_key);
    }
  } catch (const std::exception& e) {
    rejections_.reject(channel, std::string("pieces of model ") + request.model_key.substr(0, 12) + ": " + e.what());
    return;
  }
  if (file_hash_ != request.file_hash) {
    rejections_.reject(channel, "pieces of model " + request.model_key.substr(0, 12) +
                                    ": the cache file's SHA-256 is not the one asked for (the model was fitted again)");
    return;
  }
  const std::string reply = request.reply_channel.empty() ? names_.name(bus::channel::kModelPiece)
                                                          : request.reply_channel;
  const int count = protocol::piece_count(static_cast<std::int64_t>(bytes->size()));
  int sent = 0;
  for (const std::int32_t index : request.pieces) {
    if (index >= count) continue;
    model_piece_t piece = protocol::model_piece(*bytes, request.model_key, file_hash_, index);
    stamper_.stamp(piece.header);
    bus::publish_signed(lcm_, reply, piece);
    ++sent;
  }
  budget_ -= sent;
  pieces_sent_ += sent;
  std::cerr << stamper_.sender() << ": sent " << sent << " of the " << count << " pieces of model "
            << request.model_key.substr(0, 12) << " to " << reply << "\n";
}

}  // namespace wrc::geometryd
