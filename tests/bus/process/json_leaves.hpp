// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A test helper: every leaf of a JSON document by its path, to compare two run summaries field by
/// field.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace wrc::bus::test {

/// Every leaf of j by its path below path ("counters.steps", "swaps[0].t"); an empty array is a leaf.
inline void json_leaves(const nlohmann::json& j, const std::string& path, std::map<std::string, nlohmann::json>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) json_leaves(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
  } else if (j.is_array()) {
    for (size_t k = 0; k < j.size(); ++k) json_leaves(j[k], path + "[" + std::to_string(k) + "]", out);
    if (j.empty()) out[path] = j;
  } else {
    out[path] = j;
  }
}

}  // namespace wrc::bus::test
