// SPDX-License-Identifier: Apache-2.0
#include "cli/grid_option.hpp"

#include "core/contact/fastsim.hpp"

namespace wrc::cli {
namespace {

constexpr FastsimGrid kDefaultGrid{kDefaultFastsimGrid, kDefaultFastsimGrid};

std::string grid_text(const FastsimGrid& grid) {
  return std::to_string(grid.elements_per_strip) + "x" + std::to_string(grid.strips);
}

}  // namespace

OptionSpec grid_option_spec() {
  return {"--grid", true, "FASTSIM grid: elements per strip x strips", grid_text(kDefaultGrid)};
}

FastsimGrid parse_grid(const std::string& text, int min, int max) {
  const std::string::size_type x = text.find_first_of("xX");
  // A count has at most as many digits as max (so std::stoi cannot overflow), -1 otherwise.
  auto count = [&](const std::string& part) {
    if (part.empty() || part.size() > std::to_string(max).size() ||
        part.find_first_not_of("0123456789") != std::string::npos)
      return -1;
    return std::stoi(part);
  };
  const int m = x == std::string::npos ? -1 : count(text.substr(0, x));
  const int n = x == std::string::npos ? -1 : count(text.substr(x + 1));
  if (m < min || n < min || m > max || n > max) {
    throw UsageError("--grid: '" + text + "' is not MxN with whole numbers in " + std::to_string(min) + ".." +
                     std::to_string(max) + " (e.g. " + grid_text(kDefaultGrid) + ")");
  }
  return {m, n};
}

FastsimGrid grid_option(const Options& options, int min, int max) {
  return options.has("--grid") ? parse_grid(options.text("--grid"), min, max) : kDefaultGrid;
}

}  // namespace wrc::cli
