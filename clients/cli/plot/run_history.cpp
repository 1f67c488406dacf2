// SPDX-License-Identifier: Apache-2.0
#include "cli/plot/run_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "core/dynamics/wheel_output.hpp"
#include "core/numerics/number_text.hpp"
#include "wrc/wheelset_state_t.hpp"
#include "wrc/wheelset_states_t.hpp"

namespace wrc::cli::plot {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) {
    if (!field.empty() && field.back() == '\r') field.pop_back();
    fields.push_back(field);
  }
  return fields;
}

// An LCM log (wrc record) starts with the event sync word 0xEDA1DA01.
bool is_lcm_log(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[4] = {0, 0, 0, 0};
  in.read(reinterpret_cast<char*>(magic), 4);
  return in && magic[0] == 0xED && magic[1] == 0xA1 && magic[2] == 0xDA && magic[3] == 0x01;
}

// The wheelset states of the first run in a log (channel WHEELSET_STATE with any prefix: batches of
// states, or single states as logs recorded before the batches hold them), by wheelset and sorted
// by time; repeated states (the same wheelset and time) once.
std::map<int, RunHistory> read_log_history(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error("cannot read the LCM log '" + path + "'");
  const std::string channel = "WHEELSET_STATE";
  std::map<std::pair<int, double>, wheelset_state_t> states;  // by wheelset, time
  std::string run_id;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    const std::string& name = e->channel;
    if (name.size() < channel.size() || name.compare(name.size() - channel.size(), channel.size(), channel) != 0)
      continue;
    // The trailer after the message is ignored; anything else is not a state. A count beyond the
    // log's own bytes (a corrupt log) fails the decoding, or the allocation, and is skipped.
    wheelset_states_t batch;
    bool decoded = false;
    try {
      decoded = batch.decode(e->data, 0, e->datalen) >= 0 && batch.num_states >= 0 &&
                batch.num_states <= wheelset_states_t::MAX_STATES;
    } catch (const std::exception&) {
      decoded = false;
    }
    if (!decoded) {
      batch.states.assign(1, wheelset_state_t{});
      if (batch.states[0].decode(e->data, 0, e->datalen) < 0) continue;
    }
    for (const wheelset_state_t& m : batch.states) {
      if (run_id.empty()) run_id = m.run_id;
      if (m.run_id == run_id) states[{m.wheelset, m.t}] = m;
    }
  }
  if (states.empty()) throw std::runtime_error("'" + path + "' holds no wheelset states (WHEELSET_STATE)");
  std::map<int, RunHistory> histories;
  for (const auto& [when, m] : states) {
    RunHistory& history = histories[when.first];
    RunHistory::Forces& f = history.forces;
    history.t.push_back(m.t);
    history.y.push_back(m.y);
    history.yaw.push_back(m.yaw);
    history.s_right.push_back(m.s_wheel[1]);
    history.normal_force_right.push_back(m.normal_force[1]);
    if (history.models.empty() || history.models.back() != m.model) history.models.push_back(m.model);
    f.distance.push_back(m.x);
    f.y_over_q_left.push_back(y_over_q(m.lateral_force[0], m.vertical_force[0]));
    f.y_over_q_right.push_back(y_over_q(m.lateral_force[1], m.vertical_force[1]));
    f.nadal_limit.push_back(m.nadal_limit);
    f.track_shift_force.push_back(track_shift_force(m.lateral_force[0], m.lateral_force[1]));
    f.prudhomme_limit.push_back(m.prudhomme_limit);
    f.wear_number_left.push_back(m.wear_number[0]);
    f.wear_number_right.push_back(m.wear_number[1]);
  }
  return histories;
}

}  // namespace

std::map<int, RunHistory> read_wheelset_histories(const std::string& path) {
  if (is_lcm_log(path)) return read_log_history(path);
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the run history '" + path + "'");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("'" + path + "' is empty (expected a wrc run --history file)");
  std::vector<std::string> header = split(line);
  // "name [unit]" -> "name" (files before the units: "name").
  for (std::string& name : header)
    if (const std::size_t bracket = name.find(" ["); bracket != std::string::npos && name.back() == ']')
      name.erase(bracket);
  auto column = [&](const std::string& name, bool required) -> int {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      if (required) throw std::runtime_error("'" + path + "' has no column '" + name + "' (expected a wrc run --history file)");
      return -1;
    }
    return static_cast<int>(it - header.begin());
  };
  const int t = column("t", true), y = column("y", true), s = column("s_right", true),
            force = column("normal_force_right", true), model = column("model", false),
            wheelset = column("wheelset", false), yaw = column("yaw", false);
  // The force columns, all or none (a file written before they existed has none).
  const std::vector<std::pair<const char*, std::vector<double> RunHistory::Forces::*>> force_columns{
      {"distance", &RunHistory::Forces::distance},
      {"y_over_q_left", &RunHistory::Forces::y_over_q_left},
      {"y_over_q_right", &RunHistory::Forces::y_over_q_right},
      {"nadal_limit", &RunHistory::Forces::nadal_limit},
      {"track_shift_force", &RunHistory::Forces::track_shift_force},
      {"prudhomme_limit", &RunHistory::Forces::prudhomme_limit},
      {"wear_number_left", &RunHistory::Forces::wear_number_left},
      {"wear_number_right", &RunHistory::Forces::wear_number_right},
  };
  const bool has_forces = column(force_columns.front().first, false) >= 0;
  std::vector<int> force_index;
  for (const auto& [name, member] : force_columns) force_index.push_back(column(name, has_forces));
  std::map<int, RunHistory> histories;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    auto value = [&](int index) {
      if (index >= static_cast<int>(fields.size()))
        throw std::runtime_error(path + ":" + std::to_string(number) + ": missing column '" + header[index] + "'");
      const std::string& text = fields[index];
      // Y/Q of an unloaded wheel is written as nan (std::ostream), and read back as NaN.
      if (text == "nan" || text == "-nan") return std::numeric_limits<double>::quiet_NaN();
      const std::optional<double> v = whole_number(text);
      if (!v)
        throw std::runtime_error(path + ":" + std::to_string(number) + ": '" + text + "' in column '" + header[index] +
                                 "' is not a number");
      return *v;
    };
    RunHistory& history = histories[wheelset >= 0 ? static_cast<int>(value(wheelset)) : 0];
    history.t.push_back(value(t));
    history.y.push_back(value(y));
    history.yaw.push_back(yaw >= 0 ? value(yaw) : std::numeric_limits<double>::quiet_NaN());
    history.s_right.push_back(value(s));
    history.normal_force_right.push_back(value(force));
    if (has_forces)
      for (std::size_t k = 0; k < force_columns.size(); ++k)
        (history.forces.*force_columns[k].second).push_back(value(force_index[k]));
    if (model >= 0 && model < static_cast<int>(fields.size()) &&
        (history.models.empty() || history.models.back() != fields[model]))
      history.models.push_back(fields[model]);
  }
  if (histories.empty()) throw std::runtime_error("'" + path + "' has no rows");
  return histories;
}

RunHistory read_run_history(const std::string& path) { return read_wheelset_histories(path).begin()->second; }

}  // namespace wrc::cli::plot
