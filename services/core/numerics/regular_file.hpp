// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one way wrc reads an input file (profiles, run parameters, track layouts, irregularities):
/// a regular file of a bounded size, its kind checked on the open descriptor (a FIFO, a device such
/// as /dev/zero, a directory or a socket is refused without blocking and without reading), the file
/// named in every error.

#include <cstddef>
#include <stdexcept>
#include <string>

namespace wrc {

/// A file that cannot be read as an input file. what() is "<path>: <reason>".
class FileReadError : public std::invalid_argument {
 public:
  FileReadError(const std::string& path, const std::string& reason)
      : std::invalid_argument(path + ": " + reason), reason_(reason) {}
  /// The reason alone: "cannot open file (<errno text>)", "not a regular file (a FIFO)",
  /// "file too large: N bytes (at most M)", "read error (<errno text>)".
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

/// The bytes of the regular file at path, at most max_bytes [B] of them (also when the file grows
/// while it is read).
/// @throws FileReadError as described there.
std::string read_regular_file(const std::string& path, std::size_t max_bytes);

}  // namespace wrc
