// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_results.hpp"

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "cli/run_outputs.hpp"
#include "cli/run_session.hpp"
#include "cli/speed_scan_option.hpp"
#include "cli/sweep/in_process_run.hpp"
#include "cli/vehicle_stability.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/run_counter_table.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/identity/geometry_key.hpp"
#include "wrc/run_status_t.hpp"

namespace wrc::cli {
namespace {

// A point's run on the bus: on a wrc-dynamicsd of its own (named after this process, started for
// the run and stopped after it), its contact from the services on the bus (their queries spread
// over the READY instances of the model).
run_summary_t run_on_bus(const std::vector<std::string>& arguments, protocol::RunRequest request) {
  const Options o("run", "", run_option_specs(), arguments);
  request.dynamics_instance = "sweep-" + std::to_string(::getpid());
  RunSession session(o, request);
  session.start_services();
  return session.run();
}

// A point's run id: on the bus, where several sweeps may run at once, with this process's id too.
std::string sweep_run_id(std::size_t point, bool bus) {
  return (bus ? "sweep-" + std::to_string(::getpid()) + "-point-" : std::string("sweep-point-")) +
         std::to_string(point);
}

constexpr const char* kCriticalSpeed = "critical_speed";
constexpr const char* kCriticalFrequency = "critical_frequency";
// The group and column of the instances that answered a run's queries over the bus:
// "spline/a=462 spline/b=462" (model/instance=queries, space-separated; empty in-process).
constexpr const char* kInstances = "instances";
constexpr const char* kQueryInstances = "query_instances";

std::string instances_text(const nlohmann::json& instances) {
  std::string text;
  for (const auto& [name, queries] : instances.items()) text += (text.empty() ? "" : " ") + name + "=" + queries.dump();
  return text;
}

// The keys of the summary's final_state in the order cli/run_outputs.cpp writes them, with their
// units (those of the same values in the history CSV). result_columns() checks each against a summary.
const std::vector<std::pair<std::string, std::string>>& final_state_units() {
  static const std::vector<std::pair<std::string, std::string>> units{
      {"y", "m"},          {"z", "m"},          {"roll", "rad"},        {"yaw", "rad"},
      {"y_dot", "m/s"},    {"z_dot", "m/s"},    {"roll_dot", "rad/s"},  {"yaw_dot", "rad/s"},
      {"spin_rate", "rad/s"}, {"normal_force_left", "N"}, {"normal_force_right", "N"},
      {"s_wheel_left", "m"},  {"s_wheel_right", "m"}};
  return units;
}

// Top-level keys of the summary a path may start with.
const std::vector<std::string>& extractable() {
  static const std::vector<std::string> keys{"final_state", "run_quantities", "counters", "parameters",
                                             "t_end",       "model",          "formulation"};
  return keys;
}

std::string number_text(double v) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, ptr) : "";
}

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  std::string part;
  while (std::getline(in, part, '.')) parts.push_back(part);
  return parts;
}

const nlohmann::json* at_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* node = &j;
  for (const std::string& part : split_path(path)) {
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
  }
  return node;
}

// The unit of the value at path of a summary (summary: one of them, for run_quantities' units).
std::string unit_of(const std::string& path, const nlohmann::json& summary) {
  const std::vector<std::string> parts = split_path(path);
  const std::string& top = parts.front();
  if (top == "t_end") return "s";
  if (top == "final_state" && parts.size() == 2)
    for (const auto& [key, unit] : final_state_units())
      if (parts[1] == key) return unit;
  if (top == "counters" && parts.size() == 2)
    for (const auto& c : run_counter_table())
      if (parts[1] == c.key) return c.unit;
  if (top == "parameters" && parts.size() == 2)
    for (const auto& p : run_parameter_table())
      if (parts[1] == p.key) return p.unit;
  if (top == "run_quantities" && parts.size() >= 2) {
    const nlohmann::json& units = summary["run_quantities"]["units"];
    const std::string& last = parts.back();
    if (last == "t" || last == "distance") return units.value(last, "-");
    return units.value(parts[1], "-");
  }
  return "-";
}

// Every number under run_quantities (but its units), depth first.
void numbers_under(const nlohmann::json& j, const std::string& prefix, std::vector<std::string>& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (it.key() == "units") continue;
    const std::string path = prefix + "." + it.key();
    if (it->is_object()) {
      // A maximum's own value, without where it occurred (a path gives those: ...left.t).
      if (it->contains("max") && (*it)["max"].is_number())
        out.push_back(path + ".max");
      else
        numbers_under(*it, path, out);
    } else if (it->is_number()) {
      out.push_back(path);
    }
  }
}

std::string leaf_text(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return number_text(v.get<double>());
  return v.dump();
}

// The critical speed and its frequency of the run's wheelset (its lateral load set to 0: a centred
// steady state has none, as `wrc stability` does), or of its vehicle of several bodies, over
// speeds "FROM:TO:STEP" [m/s].
std::pair<std::string, std::string> critical_speed_of(const protocol::RunRequest& request, const std::string& speeds) {
  const std::vector<double> scan_speeds = critical_speed_scan(speeds);
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(request.geometry));
  const auto contact = in_process_contact(request.model, geometry, request.spline_fit);
  RunSpec spec = request.spec;
  if (!request.vehicle) spec.wheelset.lateral_force = 0.0;  // a vehicle's loads are its file's
  const CriticalSpeed c =
      linear_critical_speed(spec, request.vehicle, contact, request.geometry.track.nominal_radius, scan_speeds);
  if (!c.found) return {"", ""};
  return {number_text(c.speed), number_text(c.frequency)};
}

}  // namespace

std::vector<double> critical_speed_scan(const std::string& text) { return parse_speed_scan(text, "--critical-speeds"); }

const std::vector<std::string>& extract_groups() {
  static const std::vector<std::string> groups{"final", "maxima", "counters", "critical_speed", kInstances};
  return groups;
}

std::vector<ResultColumn> result_columns(const std::vector<std::string>& extract, const protocol::RunRequest& example) {
  const nlohmann::json summary = summary_json(run_summary_t{}, example, "");
  std::vector<std::string> paths;
  for (const std::string& item : extract) {
    if (item == "final") {
      if (summary["final_state"].size() != final_state_units().size())
        throw std::logic_error("sweep: the summary's final_state has keys without a unit here");
      for (const auto& [key, unit] : final_state_units()) {
        if (!summary["final_state"].contains(key)) throw std::logic_error("sweep: final_state has no " + key);
        paths.push_back("final_state." + key);
      }
      paths.push_back("t_end");
    } else if (item == "maxima") {
      numbers_under(summary["run_quantities"], "run_quantities", paths);
    } else if (item == "counters") {
      for (const auto& c : run_counter_table()) paths.push_back(std::string("counters.") + c.key);
    } else if (item == kCriticalSpeed) {
      paths.push_back(kCriticalSpeed);
      paths.push_back(kCriticalFrequency);
    } else if (item == kInstances) {
      paths.push_back(kQueryInstances);
    } else {
      const std::string top = split_path(item).empty() ? "" : split_path(item).front();
      const nlohmann::json* leaf = at_path(summary, item);
      if (std::find(extractable().begin(), extractable().end(), top) == extractable().end() || !leaf ||
          leaf->is_object() || leaf->is_array())
      {
        std::string groups;
        for (const std::string& g : extract_groups()) groups += (groups.empty() ? "" : ", ") + g;
        throw UsageError("--extract " + item + ": neither a group (" + groups +
                         ") nor the path of a value in a run "
                         "summary under final_state, run_quantities, counters, parameters, t_end, model, formulation "
                         "(e.g. run_quantities.y_over_q.left.t)");
      }
      paths.push_back(item);
    }
  }
  std::vector<ResultColumn> columns;
  for (const std::string& p : paths) {
    ResultColumn c{p, p == kCriticalSpeed ? "m/s" : p == kCriticalFrequency ? "Hz" : p == kQueryInstances ? "-" : unit_of(p, summary)};
    const bool repeated = std::any_of(columns.begin(), columns.end(), [&](const ResultColumn& o) { return o.path == p; });
    if (repeated) throw UsageError("--extract: " + p + " comes twice");
    columns.push_back(c);
  }
  if (columns.empty()) throw UsageError("--extract: nothing to extract");
  return columns;
}

sweep::SweepRow run_sweep_point(const SweepDefinition& definition, const std::vector<ResultColumn>& columns,
                                std::size_t point, const std::vector<std::string>& values) {
  const auto start = std::chrono::steady_clock::now();
  sweep::SweepRow row;
  row.point = point;
  row.results.assign(columns.size(), "");
  bool wants_run = false, wants_critical = false;
  for (const ResultColumn& c : columns) {
    const bool critical = c.path == kCriticalSpeed || c.path == kCriticalFrequency;
    wants_critical = wants_critical || critical;
    wants_run = wants_run || !critical;
  }
  std::vector<std::string> errors;
  try {
    const std::vector<std::string> arguments = run_arguments(definition, values);
    const protocol::RunRequest request =
        sweep_run_request(arguments, sweep_run_id(point, definition.bus), std::cerr, definition.bus);
    nlohmann::json summary;
    row.status = "finished";
    if (wants_run) {
      const run_summary_t s = definition.bus ? run_on_bus(arguments, request) : run_in_process(request);
      summary = summary_json(s, request, geometry_key(request.geometry));
      row.status = protocol::run_state_name(s.state);
      if (s.state != run_status_t::FINISHED) errors.push_back(s.message.empty() ? "the run did not finish" : s.message);
    }
    std::pair<std::string, std::string> critical;
    if (wants_critical) {
      try {
        critical = critical_speed_of(request, definition.critical_speeds);
      } catch (const std::exception& e) {
        row.status = "failed";
        errors.push_back(std::string("critical speed: ") + e.what());
      }
    }
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i].path == kCriticalSpeed) {
        row.results[i] = critical.first;
      } else if (columns[i].path == kCriticalFrequency) {
        row.results[i] = critical.second;
      } else if (columns[i].path == kQueryInstances) {
        row.results[i] = instances_text(summary.value(kQueryInstances, nlohmann::json::object()));
      } else if (const nlohmann::json* v = at_path(summary, columns[i].path)) {
        row.results[i] = leaf_text(*v);
      }
    }
  } catch (const std::exception& e) {
    row.status = "failed";
    errors.push_back(e.what());
  }
  for (std::size_t i = 0; i < errors.size(); ++i) row.error += (i ? "; " : "") + errors[i];
  row.wall_time = number_text(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return row;
}

}  // namespace wrc::cli
