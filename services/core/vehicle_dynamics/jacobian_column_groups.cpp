// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/jacobian_column_groups.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace wrc {
namespace {

bool meet(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  for (std::size_t i : a)
    if (std::binary_search(b.begin(), b.end(), i)) return true;
  return false;
}

}  // namespace

JacobianColumnGroups jacobian_column_groups(const VehicleDescription& vehicle) {
  const std::size_t n = vehicle.bodies.size();
  std::map<std::string, std::size_t> index;
  for (std::size_t b = 0; b < n; ++b) index[vehicle.bodies[b].name] = b;
  JacobianColumnGroups g;
  g.neighbourhood.resize(n);
  for (std::size_t b = 0; b < n; ++b) g.neighbourhood[b].push_back(b);
  for (const VehicleElement& e : vehicle.elements) {
    const auto a = index.find(e.bodies[0]), b = index.find(e.bodies[1]);
    if (a == index.end() || b == index.end()) continue;  // to the track
    g.neighbourhood[a->second].push_back(b->second);
    g.neighbourhood[b->second].push_back(a->second);
  }
  for (std::vector<std::size_t>& around : g.neighbourhood) {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  for (std::size_t b = 0; b < n; ++b) {
    auto group = std::find_if(g.groups.begin(), g.groups.end(), [&](const std::vector<std::size_t>& members) {
      return std::none_of(members.begin(), members.end(),
                          [&](std::size_t m) { return meet(g.neighbourhood[m], g.neighbourhood[b]); });
    });
    if (group == g.groups.end()) {
      g.groups.push_back({b});
    } else {
      group->push_back(b);
    }
  }
  return g;
}

}  // namespace wrc
