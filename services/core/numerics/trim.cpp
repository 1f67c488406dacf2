// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/trim.hpp"

namespace wrc {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n\f\v");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n\f\v");
  return text.substr(first, last - first + 1);
}

}  // namespace wrc
