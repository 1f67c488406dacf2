// SPDX-License-Identifier: Apache-2.0
#include "bus/process/launch_profile.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace wrc::bus {

std::vector<LaunchEntry> parse_launch_profile(const std::string& text, const std::string& source) {
  std::vector<LaunchEntry> entries;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    LaunchEntry entry;
    entry.line = number;
    if (!(words >> entry.name)) continue;  // blank or comment line
    if (!(words >> entry.executable)) {
      throw std::invalid_argument(source + ":" + std::to_string(number) + ": service '" + entry.name +
                                  "' has no executable");
    }
    for (std::string word; words >> word;) entry.args.push_back(word);
    auto same = [&](const LaunchEntry& e) { return e.name == entry.name; };
    if (std::any_of(entries.begin(), entries.end(), same)) {
      throw std::invalid_argument(source + ":" + std::to_string(number) + ": service '" + entry.name +
                                  "' is defined twice");
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::vector<LaunchEntry> read_launch_profile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read launch profile '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_launch_profile(text.str(), path);
}

std::vector<LaunchEntry> select_services(const std::vector<LaunchEntry>& profile,
                                         const std::vector<std::string>& names) {
  if (names.empty()) return profile;
  std::vector<LaunchEntry> selected;
  for (const auto& name : names) {
    auto it = std::find_if(profile.begin(), profile.end(), [&](const auto& e) { return e.name == name; });
    if (it == profile.end()) {
      std::string known;
      for (const auto& e : profile) known += (known.empty() ? "" : ", ") + e.name;
      throw std::invalid_argument("unknown service '" + name + "' (the profile has: " + known + ")");
    }
    if (std::none_of(selected.begin(), selected.end(), [&](const auto& e) { return e.name == name; })) {
      selected.push_back(*it);
    }
  }
  return selected;
}

}  // namespace wrc::bus
