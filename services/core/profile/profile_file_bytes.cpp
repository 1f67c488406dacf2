// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_file_bytes.hpp"

#include "core/numerics/regular_file.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {

std::string read_profile_file_bytes(const std::string& path) {
  try {
    return read_regular_file(path, kMaxProfileFileBytes);
  } catch (const FileReadError& e) {
    throw ProfileError(path, 0, e.reason());
  }
}

}  // namespace wrc
