// SPDX-License-Identifier: Apache-2.0
#include "cli/speed_scan_option.hpp"

#include <sstream>
#include <stdexcept>

#include "cli/options.hpp"
#include "core/dynamics/linear_stability.hpp"

namespace wrc::cli {

std::vector<double> parse_speed_scan(const std::string& text, const std::string& option) {
  std::vector<double> parts;
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ':')) parts.push_back(parse_finite(item, option));
  if (parts.size() != 3) throw UsageError(option + ": '" + text + "' is not FROM:TO:STEP [m/s] (e.g. 5:80:1)");
  try {
    return stability_speeds(parts[0], parts[1], parts[2]);
  } catch (const std::invalid_argument& e) {
    throw UsageError(option + ": " + e.what());
  }
}

}  // namespace wrc::cli
