// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_error.hpp"

namespace wrc {
namespace {
std::string format_message(const std::string& source, int line, const std::string& reason) {
  if (line > 0) {
    return source + ":" + std::to_string(line) + ": " + reason;
  }
  return source + ": " + reason;
}
}  // namespace

ProfileError::ProfileError(const std::string& source, int line, const std::string& reason)
    : std::runtime_error(format_message(source, line, reason)),
      source_(source),
      line_(line),
      reason_(reason) {}

}  // namespace wrc
