// SPDX-License-Identifier: Apache-2.0
#include "cli/plot/plot_kind.hpp"

#include <algorithm>

namespace wrc::cli::plot {
namespace {
std::vector<PlotKind>& registry() {
  static std::vector<PlotKind> kinds;
  return kinds;
}
}  // namespace

std::vector<PlotKind> plot_kinds() {
  std::vector<PlotKind> kinds = registry();
  std::stable_sort(kinds.begin(), kinds.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  return kinds;
}

PlotKindRegistrar::PlotKindRegistrar(PlotKind kind) { registry().push_back(std::move(kind)); }

}  // namespace wrc::cli::plot
