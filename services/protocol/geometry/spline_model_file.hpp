// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The spline model on disk: the model file (the LCM encoding of spline_model_t with the
/// coefficients inline), the reference message that points to it, and resolving a reference back
/// to the complete model with its size and SHA-256 checked.

#include <string>
#include <vector>

#include "wrc/spline_model_t.hpp"

namespace wrc::protocol {

/// Writes message (inline coefficients) to path atomically (temporary file, then rename) and
/// returns the reference to publish: the same message without coefficients and with file_path,
/// file_hash (SHA-256 of the bytes) and file_size. @throws std::runtime_error naming the path.
spline_model_t write_model_file(const spline_model_t& message, const std::string& path);

/// The reference to an existing model file holding full (the message written there): full
/// without coefficients, with file_path (absolute), file_hash (SHA-256 of the file's bytes as they
/// are now) and file_size. @throws std::runtime_error when the file cannot be read.
spline_model_t file_reference(const spline_model_t& full, const std::string& path);

/// Reads and decodes a model file (no reference to check against: a cache lookup).
/// @throws std::runtime_error naming the path when it is missing or does not decode.
spline_model_t read_model_file(const std::string& path);

/// The complete message behind a reference: itself when the coefficients are inline, otherwise
/// read from file_path, checked against file_size and file_hash, decoded.
/// @throws std::runtime_error naming the path and what does not match.
spline_model_t resolve_model(const spline_model_t& reference);

/// The complete message behind a reference from the file's bytes as they came (read, or put
/// together from pieces, already checked against file_size and file_hash): decoded, and holding
/// the reference's model_key and model_hash. @throws std::runtime_error naming where what does
/// not match (where: the path, or "from pieces").
spline_model_t model_from_file_bytes(const spline_model_t& reference, const std::vector<char>& bytes,
                                     const std::string& where);
}  // namespace wrc::protocol
