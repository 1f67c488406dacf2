// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_work.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/options.hpp"

namespace wrc::cli {
namespace fs = std::filesystem;

SweepWork::SweepWork(std::string directory) : directory_(fs::absolute(directory).lexically_normal().string()) {
  while (directory_.size() > 1 && directory_.back() == '/') directory_.pop_back();
}

std::string SweepWork::row_path(std::size_t point) const { return directory_ + "/rows/" + std::to_string(point) + ".json"; }
std::string SweepWork::log_path(std::size_t point) const { return logs_directory() + "/point-" + std::to_string(point) + ".log"; }

void SweepWork::prepare(const SweepDefinition& definition) const {
  std::error_code ec;
  for (const std::string& d : {directory_, directory_ + "/rows", logs_directory(), slurm_directory()}) {
    fs::create_directories(d, ec);
    if (ec) throw UsageError("--work-dir " + d + ": cannot be created: " + ec.message());
  }
  if (fs::exists(definition_path())) {
    if (!(this->definition() == definition))
      throw UsageError("--work-dir " + directory_ + " holds another sweep (its sweep.json: other grid, run options or "
                       "extraction); remove it, or give this sweep another --out or --work-dir");
    return;
  }
  const std::string temporary = definition_path() + ".tmp";
  {
    std::ofstream out(temporary);
    out << definition.to_json().dump(2) << "\n";
    if (!out) throw UsageError("--work-dir " + directory_ + ": cannot write sweep.json");
  }
  fs::rename(temporary, definition_path());
}

SweepDefinition SweepWork::definition() const {
  std::ifstream in(definition_path());
  if (!in) throw UsageError(definition_path() + ": no sweep there (a sweep's --work-dir has its sweep.json)");
  try {
    return SweepDefinition::from_json(nlohmann::json::parse(in), definition_path());
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(definition_path() + ": not JSON (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

void SweepWork::write_row(const sweep::SweepRow& row, const sweep::Grid& grid) const {
  const nlohmann::json j{{"point", row.point},   {"values", grid.point(row.point)}, {"status", row.status},
                         {"results", row.results}, {"error", row.error},            {"wall_time", row.wall_time}};
  const std::string path = row_path(row.point);
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    out << j.dump() << "\n";
    out.flush();
    if (!out) throw std::runtime_error(temporary + ": cannot be written");
  }
  fs::rename(temporary, path);
}

std::optional<sweep::SweepRow> SweepWork::read_row(std::size_t point, const sweep::SweepLayout& layout) const {
  const std::string path = row_path(point);
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    sweep::SweepRow row;
    row.point = j.at("point").get<std::size_t>();
    row.status = j.at("status").get<std::string>();
    row.results = j.at("results").get<std::vector<std::string>>();
    row.error = j.at("error").get<std::string>();
    row.wall_time = j.at("wall_time").get<std::string>();
    if (row.point != point || j.at("values").get<std::vector<std::string>>() != layout.grid().point(point) ||
        row.results.size() != layout.result_count())
      throw std::invalid_argument("not a row of point " + std::to_string(point) + " of this sweep");
    return row;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

std::size_t SweepWork::gather(const sweep::SweepLayout& layout, std::map<std::size_t, sweep::SweepRow>& rows) const {
  std::size_t added = 0;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(directory_ + "/rows", ec)) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".json") continue;
    const std::string stem = e.path().stem().string();
    if (stem.empty() || stem.find_first_not_of("0123456789") != std::string::npos || stem.size() > 12) continue;
    const std::size_t point = std::stoul(stem);
    if (point >= layout.grid().size() || rows.count(point)) continue;
    if (auto row = read_row(point, layout)) {
      rows.emplace(point, *row);
      ++added;
    }
  }
  return added;
}

void SweepWork::forget(std::size_t point) const {
  std::error_code ec;
  fs::remove(row_path(point), ec);
}

}  // namespace wrc::cli
