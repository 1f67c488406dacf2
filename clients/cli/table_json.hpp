// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A parameter set as JSON, generated from its table (core/numerics/parameter_table.hpp): what
/// `wrc run` writes as a summary's parameters and counters and `wrc fit --report` as the fit
/// options and the track.

#include <vector>

#include <nlohmann/json.hpp>

#include "core/numerics/parameter_table.hpp"

namespace wrc::cli {

/// The members of value as a JSON object, each by its table key: booleans as true / false, whole
/// numbers as integers.
template <class Entry, class T>
nlohmann::json table_json(const std::vector<Entry>& table, const T& value) {
  nlohmann::json j = nlohmann::json::object();
  for (const Entry& p : table) {
    const double v = p.get(value);
    if (p.kind == ParameterKind::kBoolean)
      j[p.key] = v != 0.0;
    else if (p.kind == ParameterKind::kInteger)
      j[p.key] = static_cast<long long>(v);
    else
      j[p.key] = v;
  }
  return j;
}

}  // namespace wrc::cli
