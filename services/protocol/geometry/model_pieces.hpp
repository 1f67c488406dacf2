// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A spline model file carried over the bus in pieces (model_piece_t), for a spline service on a
/// machine that cannot read wrc-geometryd's cache: cutting a file into its pieces, and putting
/// the pieces of one file back together, in any order, with duplicates and losses, the whole
/// used only when its size and SHA-256 are the reference's. No transport here.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "wrc/model_piece_request_t.hpp"
#include "wrc/model_piece_t.hpp"
#include "wrc/spline_model_t.hpp"

namespace wrc::protocol {

/// [B] the largest model file that travels in pieces (model_piece_t::file_size).
inline constexpr std::int64_t kMaxPiecedFileBytes = 2147483647;

/// Pieces of a file of file_size bytes [B]: ceil(file_size / PIECE_BYTES).
/// @throws std::invalid_argument when file_size is not in 1..kMaxPiecedFileBytes.
int piece_count(std::int64_t file_size);

/// Piece index of the file bytes (header not stamped), naming the file by model_key and its
/// SHA-256 file_hash. @throws std::invalid_argument when index is not a piece of bytes.
model_piece_t model_piece(const std::vector<char>& bytes, const std::string& model_key, const std::string& file_hash,
                          int index);

/// Why a request cannot be answered as it stands (no pieces, too many, an index below 0), or
/// nothing; indices beyond a file's last piece are the answerer's to leave out.
std::optional<std::string> piece_request_violation(const model_piece_request_t& request);

/// The pieces of the one file a reference names, as they come.
class ModelPieces {
 public:
  /// For the file of reference (model_key, file_hash, file_size): none received yet.
  /// @throws std::invalid_argument when the reference names no file or its size is out of range.
  explicit ModelPieces(const spline_model_t& reference);

  /// Takes piece (a duplicate is taken again, unchanged). Returns why it is refused: another
  /// file, an index or a piece count that does not fit the file, a piece of the wrong length.
  std::optional<std::string> add(const model_piece_t& piece);
  /// Whether the piece belongs to this file (model_key and file_hash), whatever else it says.
  bool names_this_file(const model_piece_t& piece) const;
  /// The indices not yet received, in increasing order, at most at_most of them.
  std::vector<int> missing(std::size_t at_most) const;
  int received() const { return received_; }
  int count() const { return static_cast<int>(have_.size()); }
  bool complete() const { return received_ == count(); }
  /// The whole file, once complete: its bytes when their SHA-256 is file_hash. Otherwise a piece
  /// was corrupt: every piece is forgotten (all are asked for again) and std::runtime_error says so.
  std::vector<char> take_file();

  const std::string& model_key() const { return model_key_; }
  const std::string& file_hash() const { return file_hash_; }
  std::int64_t file_size() const { return file_size_; }

 private:
  std::string model_key_;
  std::string file_hash_;
  std::int64_t file_size_ = 0;
  std::vector<char> bytes_;
  std::vector<bool> have_;
  int received_ = 0;
};

}  // namespace wrc::protocol
