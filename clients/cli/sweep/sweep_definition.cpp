// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_definition.hpp"

#include <algorithm>
#include <optional>

#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "cli/run_options.hpp"
#include "cli/service_starter.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/geometry/track_table.hpp"

namespace wrc::cli {
namespace {

// `wrc run` options a grid key may name besides the parameter tables' (each unit-less).
const std::vector<std::string>& run_option_keys() {
  static const std::vector<std::string> keys{"model", "suspension", "params", "track", "irregularities", "swap_at"};
  return keys;
}

// Options a sweep sets itself, or (unless its runs are on the bus) that only the bus knows: never in
// a sweep's run options.
std::vector<std::string> options_of_the_sweep(bool bus) {
  std::vector<std::string> names{"--summary", "--history", "--run-id", "--in-process", "--dynamics-instance"};
  if (!bus)
    for (const OptionSpec& s : service_start_option_specs()) names.push_back(s.name);
  return names;
}

std::string option_spelling(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return "--" + key;
}

struct GridKey {
  std::string option;  // the `wrc run` option
  std::string unit;
};

// The entry of a table whose key is key or whose option is --key.
template <class Table>
std::optional<GridKey> table_key(const Table& table, const std::string& key) {
  for (const auto& p : table) {
    if (!p.has_option()) continue;
    if (key == p.key || option_spelling(key) == p.option_name()) return GridKey{p.option_name(), p.unit};
  }
  return std::nullopt;
}

std::optional<GridKey> find_grid_key(const std::string& key) {
  if (auto k = table_key(run_parameter_table(), key)) return k;
  if (auto k = table_key(track_parameter_table(), key)) return k;
  for (const OptionSpec& s : profile_option_specs())
    if (s.name == option_spelling(key)) return GridKey{s.name, "-"};
  for (const std::string& k : run_option_keys())
    if (k == key) return GridKey{option_spelling(k), "-"};
  return std::nullopt;
}

GridKey grid_key(const std::string& key) {
  if (auto k = find_grid_key(key)) return *k;
  std::string keys;
  for (const auto& p : run_parameter_table())
    if (p.has_option()) keys += std::string(keys.empty() ? "" : ", ") + p.key;
  throw UsageError("--grid " + key + ": not a key a run takes; the keys: the run parameters (" + keys +
                   "), the profile and track options (wheel, rail, rail_cant, gauge, gauge_depth, flange_back_spacing, "
                   "taping_line_offset, inclination, r0) and model, suspension, params, track, irregularities, swap_at");
}

}  // namespace

nlohmann::json SweepDefinition::to_json() const {
  nlohmann::json grid = nlohmann::json::array();
  for (const sweep::GridAxis& a : axes) grid.push_back({{"key", a.key}, {"values", a.values}});
  return {{"format", "wrc-sweep-1"},
          {"grid", grid},
          {"run_options", run_options},
          {"extract", extract},
          {"critical_speeds", critical_speeds},
          {"bus", bus}};
}

SweepDefinition SweepDefinition::from_json(const nlohmann::json& j, const std::string& source) {
  try {
    if (j.at("format") != "wrc-sweep-1")
      throw std::invalid_argument("format " + j.at("format").dump() + " is not wrc-sweep-1");
    SweepDefinition d;
    for (const auto& a : j.at("grid"))
      d.axes.push_back({a.at("key").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
    d.run_options = j.at("run_options").get<std::vector<std::string>>();
    d.extract = j.at("extract").get<std::vector<std::string>>();
    d.critical_speeds = j.at("critical_speeds").get<std::string>();
    d.bus = j.value("bus", false);  // work directories written before --bus have none
    return d;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(source + ": not a sweep definition (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source + ": " + e.what());
  }
}

std::string grid_key_unit(const std::string& key) { return grid_key(key).unit; }

void check_run_options(const std::vector<std::string>& run_options, const std::vector<sweep::GridAxis>& axes,
                       bool bus) {
  const Options o("run", "", run_option_specs(), run_options);
  for (const std::string& name : options_of_the_sweep(bus))
    if (o.has(name))
      throw UsageError("run option " + name + ": a sweep sets it itself (every run is in-process or, with --bus, on "
                       "a dynamics of its own; its results go into the sweep's CSV) or it is the bus's (give it with "
                       "--bus); leave it out");
  for (const sweep::GridAxis& a : axes)
    if (o.has(grid_key(a.key).option))
      throw UsageError("run option " + grid_key(a.key).option + " is also the grid key " + a.key + ": give it once");
}

std::vector<std::string> run_arguments(const SweepDefinition& definition, const std::vector<std::string>& values) {
  std::vector<std::string> args = definition.run_options;
  for (std::size_t k = 0; k < definition.axes.size(); ++k) {
    args.push_back(grid_key(definition.axes[k].key).option);
    args.push_back(values.at(k));
  }
  return args;
}

protocol::RunRequest sweep_run_request(const std::vector<std::string>& arguments, const std::string& run_id,
                                       std::ostream& notes, bool bus) {
  std::vector<std::string> args = arguments;
  if (!bus) args.push_back("--in-process");
  args.insert(args.end(), {"--run-id", run_id});
  const Options o("run", "", run_option_specs(), args);
  return run_request_from(o, notes);
}

}  // namespace wrc::cli
