// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The one rule for reading a profile file, whoever reads it (the profile readers, the geometry
/// key's content hash, every service and command that names a profile file): a regular file of at
/// most kMaxProfileFileBytes (profile_limits.hpp), refused at once otherwise, with the file named
/// in every error. A FIFO, a device (/dev/zero, /dev/urandom), a directory or a socket is refused
/// without blocking and without reading.

#include <string>

namespace wrc {

/// The bytes of the profile file at path.
/// @throws ProfileError(path, 0, reason): "cannot open file (<errno text>)", "not a regular file
///         (a FIFO)" (a directory, a character device, ...), "file too large: N bytes (at most M)"
///         (also when the file grows beyond the limit while it is read), "read error (...)".
std::string read_profile_file_bytes(const std::string& path);

}  // namespace wrc
