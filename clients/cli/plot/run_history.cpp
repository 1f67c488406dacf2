#include "cli/plot/run_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "core/numerics/number_text.hpp"
#include "wrc/wheelset_state_t.hpp"

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

// The wheelset states of the first run in a log (channel WHEELSET_STATE with any prefix), sorted
// by time; repeated states (the same time) once.
RunHistory read_log_history(const std::string& path) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw std::runtime_error("cannot read the LCM log '" + path + "'");
  const std::string channel = "WHEELSET_STATE";
  std::map<double, wheelset_state_t> states;
  std::string run_id;
  for (const lcm::LogEvent* e = log.readNextEvent(); e != nullptr; e = log.readNextEvent()) {
    const std::string& name = e->channel;
    if (name.size() < channel.size() || name.compare(name.size() - channel.size(), channel.size(), channel) != 0)
      continue;
    wheelset_state_t m;
    if (m.decode(e->data, 0, e->datalen) < 0) continue;  // not a state (the trailer is ignored)
    if (run_id.empty()) run_id = m.run_id;
    if (m.run_id == run_id) states[m.t] = m;
  }
  if (states.empty()) throw std::runtime_error("'" + path + "' holds no wheelset states (WHEELSET_STATE)");
  RunHistory history;
  for (const auto& [t, m] : states) {
    history.t.push_back(t);
    history.y.push_back(m.y);
    history.s_right.push_back(m.s_wheel[1]);
    history.normal_force_right.push_back(m.normal_force[1]);
    if (history.models.empty() || history.models.back() != m.model) history.models.push_back(m.model);
  }
  return history;
}

}  // namespace

RunHistory read_run_history(const std::string& path) {
  if (is_lcm_log(path)) return read_log_history(path);
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the run history '" + path + "'");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("'" + path + "' is empty (expected a wrc run --history file)");
  const std::vector<std::string> header = split(line);
  auto column = [&](const std::string& name, bool required) -> int {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      if (required) throw std::runtime_error("'" + path + "' has no column '" + name + "' (expected a wrc run --history file)");
      return -1;
    }
    return static_cast<int>(it - header.begin());
  };
  const int t = column("t", true), y = column("y", true), s = column("s_right", true),
            force = column("normal_force_right", true), model = column("model", false);
  RunHistory history;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    auto value = [&](int index) {
      if (index >= static_cast<int>(fields.size()))
        throw std::runtime_error(path + ":" + std::to_string(number) + ": missing column '" + header[index] + "'");
      const std::string& text = fields[index];
      const std::optional<double> v = whole_number(text);
      if (!v)
        throw std::runtime_error(path + ":" + std::to_string(number) + ": '" + text + "' in column '" + header[index] +
                                 "' is not a number");
      return *v;
    };
    history.t.push_back(value(t));
    history.y.push_back(value(y));
    history.s_right.push_back(value(s));
    history.normal_force_right.push_back(value(force));
    if (model >= 0 && model < static_cast<int>(fields.size()) &&
        (history.models.empty() || history.models.back() != fields[model]))
      history.models.push_back(fields[model]);
  }
  if (history.t.empty()) throw std::runtime_error("'" + path + "' has no rows");
  return history;
}

}  // namespace wrc::cli::plot
