#include "cli/plot/run_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

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

}  // namespace

RunHistory read_run_history(const std::string& path) {
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
      size_t used = 0;
      double v = NAN;
      try {
        v = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size())
        throw std::runtime_error(path + ":" + std::to_string(number) + ": '" + text + "' in column '" + header[index] +
                                 "' is not a number");
      return v;
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
