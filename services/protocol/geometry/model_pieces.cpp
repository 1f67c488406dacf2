// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/model_pieces.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/identity/sha256.hpp"

namespace wrc::protocol {
namespace {

constexpr std::int64_t kPieceBytes = model_piece_t::PIECE_BYTES;

// [B] bytes of piece index of a file of size bytes.
int piece_bytes(std::int64_t size, int index) {
  return static_cast<int>(std::min<std::int64_t>(kPieceBytes, size - kPieceBytes * index));
}

}  // namespace

int piece_count(std::int64_t file_size) {
  if (file_size < 1 || file_size > kMaxPiecedFileBytes)
    throw std::invalid_argument("model file of " + std::to_string(file_size) + " bytes: pieces are for 1 to " +
                                std::to_string(kMaxPiecedFileBytes) + " bytes");
  return static_cast<int>((file_size + kPieceBytes - 1) / kPieceBytes);
}

model_piece_t model_piece(const std::vector<char>& bytes, const std::string& model_key, const std::string& file_hash,
                          int index) {
  const std::int64_t size = static_cast<std::int64_t>(bytes.size());
  const int count = piece_count(size);
  if (index < 0 || index >= count)
    throw std::invalid_argument("piece " + std::to_string(index) + " of a file of " + std::to_string(count) + " pieces");
  model_piece_t piece{};
  piece.model_key = model_key;
  piece.file_hash = file_hash;
  piece.file_size = size;
  piece.piece_count = count;
  piece.index = index;
  piece.num_bytes = piece_bytes(size, index);
  const auto begin = bytes.begin() + static_cast<std::ptrdiff_t>(kPieceBytes * index);
  piece.bytes.assign(begin, begin + piece.num_bytes);
  return piece;
}

std::optional<std::string> piece_request_violation(const model_piece_request_t& request) {
  if (request.num_pieces < 1 || request.num_pieces > model_piece_request_t::MAX_PIECES)
    return "num_pieces = " + std::to_string(request.num_pieces) + " is not 1.." +
           std::to_string(model_piece_request_t::MAX_PIECES);
  for (int i = 0; i < request.num_pieces; ++i)
    if (request.pieces[static_cast<std::size_t>(i)] < 0)
      return "pieces[" + std::to_string(i) + "] = " + std::to_string(request.pieces[static_cast<std::size_t>(i)]) +
             " is negative";
  return std::nullopt;
}

ModelPieces::ModelPieces(const spline_model_t& reference)
    : model_key_(reference.model_key), file_hash_(reference.file_hash), file_size_(reference.file_size) {
  if (reference.file_path.empty() || file_hash_.empty())
    throw std::invalid_argument("spline model " + model_key_.substr(0, 12) + " is inline: it has no pieces");
  have_.assign(static_cast<std::size_t>(piece_count(file_size_)), false);
  bytes_.assign(static_cast<std::size_t>(file_size_), '\0');
}

bool ModelPieces::names_this_file(const model_piece_t& piece) const {
  return piece.model_key == model_key_ && piece.file_hash == file_hash_;
}

std::optional<std::string> ModelPieces::add(const model_piece_t& piece) {
  if (!names_this_file(piece)) return std::string("a piece of another file");
  if (piece.file_size != file_size_ || piece.piece_count != count())
    return "file_size = " + std::to_string(piece.file_size) + " and piece_count = " +
           std::to_string(piece.piece_count) + ", the file has " + std::to_string(file_size_) + " bytes in " +
           std::to_string(count()) + " pieces";
  if (piece.index < 0 || piece.index >= count())
    return "index = " + std::to_string(piece.index) + " is not a piece of " + std::to_string(count());
  const int expected = piece_bytes(file_size_, piece.index);
  if (piece.num_bytes != expected)
    return "piece " + std::to_string(piece.index) + " has " + std::to_string(piece.num_bytes) + " bytes, not " +
           std::to_string(expected);
  const std::size_t at = static_cast<std::size_t>(kPieceBytes * piece.index);
  std::copy(piece.bytes.begin(), piece.bytes.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(at));
  if (!have_[static_cast<std::size_t>(piece.index)]) {
    have_[static_cast<std::size_t>(piece.index)] = true;
    ++received_;
  }
  return std::nullopt;
}

std::vector<int> ModelPieces::missing(std::size_t at_most) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < have_.size() && out.size() < at_most; ++i)
    if (!have_[i]) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<char> ModelPieces::take_file() {
  if (!complete())
    throw std::logic_error("ModelPieces::take_file: " + std::to_string(received_) + " of " + std::to_string(count()) +
                           " pieces");
  const std::string hash = sha256_hex(bytes_.data(), bytes_.size());
  if (hash != file_hash_) {
    std::fill(have_.begin(), have_.end(), false);
    received_ = 0;
    throw std::runtime_error("the pieces put together have the SHA-256 " + hash + ", not the file's " + file_hash_ +
                             ": a piece was corrupt; asking for all of them again");
  }
  return bytes_;
}

}  // namespace wrc::protocol
