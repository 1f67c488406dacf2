// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The file form of a message that can travel either inline or as a reference to a file
/// (spline_model_t, geometry_table_t): the message with its header, request id and file fields
/// cleared, LCM-encoded and written atomically; a reference carries the file's absolute path, size
/// and SHA-256, and the reader checks both. `what` names the kind of file in every error.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "core/identity/sha256.hpp"
#include "wrc/header_t.hpp"

namespace wrc::protocol {

/// The bytes of the file at path. @throws std::runtime_error "<what> <path> is missing" when it
/// is not a regular file, or naming the read error.
std::vector<char> read_message_file_bytes(const std::string& path, const char* what);

/// The file form of a message: M with its header, request id and file fields cleared, LCM-encoded,
/// written atomically (temporary file, then rename); returns the bytes written. what names the kind
/// in errors.
template <class M>
std::vector<char> write_message_file(M stored, const std::string& path, const char* what) {
  stored.header = header_t{};
  stored.request_id = 0;
  stored.file_path.clear();
  stored.file_hash.clear();
  stored.file_size = 0;
  const int size = stored.getEncodedSize();
  std::vector<char> bytes(static_cast<size_t>(size));
  if (stored.encode(bytes.data(), 0, size) != size) throw std::runtime_error(std::string(what) + ": encoding failed");
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), size);
    if (!out) throw std::runtime_error(std::string(what) + ": cannot write " + temporary);
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec)
    throw std::runtime_error(std::string(what) + ": cannot rename " + temporary + " to " + path + ": " + ec.message());
  return bytes;
}

/// The message of type M that bytes encode, all of them. @throws std::runtime_error naming path
/// when they do not decode as one M.
template <class M>
M decode_bytes(const std::vector<char>& bytes, const std::string& path, const char* what) {
  M full;
  if (full.decode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size()))
    throw std::runtime_error(std::string(what) + " " + path + " does not decode as a " + M::getTypeName());
  return full;
}

/// The file fields of a reference to path (absolute path, size, SHA-256 of the bytes).
template <class M>
void set_file_fields(M& reference, const std::string& path, const std::vector<char>& bytes) {
  reference.file_path = std::filesystem::absolute(path).string();
  reference.file_hash = sha256_hex(bytes.data(), bytes.size());
  reference.file_size = static_cast<int64_t>(bytes.size());
}

/// The bytes behind a reference, checked against its file size and SHA-256.
template <class M>
std::vector<char> checked_file(const M& reference, const char* what) {
  const std::string& path = reference.file_path;
  std::vector<char> bytes = read_message_file_bytes(path, what);
  if (static_cast<std::int64_t>(bytes.size()) != reference.file_size)
    throw std::runtime_error(std::string(what) + " " + path + " has " + std::to_string(bytes.size()) +
                             " bytes, the message says " + std::to_string(reference.file_size));
  const std::string hash = sha256_hex(bytes.data(), bytes.size());
  if (hash != reference.file_hash)
    throw std::runtime_error(std::string(what) + " " + path + ": SHA-256 " + hash + " differs from the message's " +
                             reference.file_hash);
  return bytes;
}
}  // namespace wrc::protocol
