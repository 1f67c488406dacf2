// SPDX-License-Identifier: Apache-2.0
// A model file carried in pieces (protocol/geometry/model_pieces.hpp): a file of 2.5 pieces cut
// and put together in any order, with duplicates and a third of the pieces lost on the first pass,
// gives back its bytes exactly; a corrupted piece makes the whole fail its SHA-256, and every piece
// is asked for again; pieces of another file, out of range or of the wrong length are refused
// naming why; a request's piece list is bounded.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "core/identity/sha256.hpp"
#include "protocol/geometry/model_pieces.hpp"

namespace wrc::protocol {
namespace {

constexpr int kPiece = model_piece_t::PIECE_BYTES;

std::vector<char> file_of(std::size_t size) {
  std::vector<char> bytes(size);
  std::mt19937 random(7);
  for (char& b : bytes) b = static_cast<char>(random() & 0xff);
  return bytes;
}

spline_model_t reference_of(const std::vector<char>& bytes) {
  spline_model_t r{};
  r.model_key = std::string(64, 'a');
  r.file_path = "/elsewhere/a.splinemodel";
  r.file_hash = sha256_hex(bytes.data(), bytes.size());
  r.file_size = static_cast<std::int64_t>(bytes.size());
  return r;
}

TEST(ModelPieces, PutTogetherInAnyOrderWithLossesAndDuplicates) {
  const std::vector<char> file = file_of(2 * kPiece + kPiece / 2);
  const spline_model_t reference = reference_of(file);
  ModelPieces pieces(reference);
  ASSERT_EQ(pieces.count(), 3);
  EXPECT_EQ(piece_count(1), 1);
  EXPECT_EQ(piece_count(kPiece), 1);
  EXPECT_EQ(piece_count(kPiece + 1), 2);
  // First pass: piece 1 lost; piece 2 (the last: half a piece) twice, before piece 0.
  for (const int i : {2, 2, 0}) EXPECT_FALSE(pieces.add(model_piece(file, reference.model_key, reference.file_hash, i)));
  EXPECT_EQ(model_piece(file, reference.model_key, reference.file_hash, 2).num_bytes, kPiece / 2);
  EXPECT_FALSE(pieces.complete());
  EXPECT_EQ(pieces.missing(10), std::vector<int>{1});
  EXPECT_FALSE(pieces.add(model_piece(file, reference.model_key, reference.file_hash, 1)));
  ASSERT_TRUE(pieces.complete());
  EXPECT_EQ(pieces.take_file(), file);
}

TEST(ModelPieces, ACorruptPieceFailsTheWholeAndAllAreAskedAgain) {
  const std::vector<char> file = file_of(3 * kPiece);
  const spline_model_t reference = reference_of(file);
  ModelPieces pieces(reference);
  for (int i = 0; i < 3; ++i) {
    model_piece_t piece = model_piece(file, reference.model_key, reference.file_hash, i);
    if (i == 1) piece.bytes[100] = static_cast<char>(piece.bytes[100] ^ 1);
    EXPECT_FALSE(pieces.add(piece));
  }
  ASSERT_TRUE(pieces.complete());
  try {
    pieces.take_file();
    ADD_FAILURE() << "a corrupt whole was given out";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a piece was corrupt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(pieces.received(), 0);
  EXPECT_EQ(pieces.missing(10), (std::vector<int>{0, 1, 2}));
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(pieces.add(model_piece(file, reference.model_key, reference.file_hash, i)));
  EXPECT_EQ(pieces.take_file(), file);
}

TEST(ModelPieces, PiecesThatDoNotFitTheFileAreRefusedNamingWhy) {
  const std::vector<char> file = file_of(kPiece + 10);
  const spline_model_t reference = reference_of(file);
  ModelPieces pieces(reference);
  const model_piece_t good = model_piece(file, reference.model_key, reference.file_hash, 1);
  model_piece_t other = good;
  other.file_hash = std::string(64, 'f');
  EXPECT_FALSE(pieces.names_this_file(other));
  EXPECT_EQ(pieces.add(other), std::string("a piece of another file"));
  model_piece_t beyond = good;
  beyond.index = 2;
  EXPECT_EQ(pieces.add(beyond), std::string("index = 2 is not a piece of 2"));
  model_piece_t short_piece = good;
  short_piece.num_bytes = 9;
  short_piece.bytes.resize(9);
  EXPECT_EQ(pieces.add(short_piece), std::string("piece 1 has 9 bytes, not 10"));
  model_piece_t resized = good;
  resized.file_size += 1;
  EXPECT_NE(pieces.add(resized)->find("file_size = "), std::string::npos);
  EXPECT_EQ(pieces.received(), 0);
  EXPECT_THROW(model_piece(file, reference.model_key, reference.file_hash, 2), std::invalid_argument);
  spline_model_t inline_model = reference;
  inline_model.file_path.clear();
  EXPECT_THROW(ModelPieces{inline_model}, std::invalid_argument);
  EXPECT_THROW(piece_count(0), std::invalid_argument);

  model_piece_request_t request{};
  EXPECT_EQ(piece_request_violation(request), std::string("num_pieces = 0 is not 1..256"));
  request.num_pieces = 2;
  request.pieces = {0, -1};
  EXPECT_EQ(piece_request_violation(request), std::string("pieces[1] = -1 is negative"));
  request.pieces = {0, 1};
  EXPECT_FALSE(piece_request_violation(request));
}

}  // namespace
}  // namespace wrc::protocol
