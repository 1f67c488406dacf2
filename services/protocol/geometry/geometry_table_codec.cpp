// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/geometry_table_codec.hpp"

#include <stdexcept>
#include <vector>

#include "core/identity/geometry_key.hpp"
#include "core/identity/sha256.hpp"
#include "protocol/geometry/message_file.hpp"
#include "protocol/geometry/track_codec.hpp"

namespace wrc::protocol {
namespace {

constexpr const char* kTableFile = "geometry table file";

// SHA-256 of a table's values as little-endian doubles.
std::string values_hash(const std::vector<double>& values) { return sha256_hex_of_doubles(values); }

// The same for a table (full without its values).
geometry_table_t table_reference_to(const geometry_table_t& full, const std::string& path,
                                    const std::vector<char>& bytes) {
  geometry_table_t reference = full;
  reference.num_values = 0;
  reference.values.clear();
  set_file_fields(reference, path, bytes);
  return reference;
}

}  // namespace

geometry_table_t encode_table(const WheelSampleGrid& grid, const GeometrySpec& spec, const std::string& model_key) {
  geometry_table_t t;
  t.request_id = 0;
  t.geometry_key = geometry_key(spec);
  t.model_key = model_key;
  t.version = kGeometryTableVersion;
  t.track = to_message(spec);
  t.wheel = grid.side == WheelSide::kLeft ? geometry_table_t::LEFT : geometry_table_t::RIGHT;
  t.y_min = grid.y.front();
  t.y_max = grid.y.back();
  t.y_count = static_cast<int32_t>(grid.y.size());
  t.roll_min = grid.roll.front();
  t.roll_max = grid.roll.back();
  t.roll_count = static_cast<int32_t>(grid.roll.size());
  t.yaw_min = grid.yaw.front();
  t.yaw_max = grid.yaw.back();
  t.yaw_count = static_cast<int32_t>(grid.yaw.size());
  for (const SplineFieldInfo& f : kSplineFields) {
    t.column_names.push_back(f.name);
    t.column_units.push_back(f.unit);
  }
  t.column_names.insert(t.column_names.end(), {"valid", "second_minimum_gap", "jump_distance"});
  t.column_units.insert(t.column_units.end(), {"-", "m", "m"});
  t.num_columns = static_cast<int32_t>(t.column_names.size());
  t.values.reserve(grid.samples.size() * static_cast<size_t>(t.num_columns));
  for (size_t j = 0; j < grid.roll.size(); ++j)
    for (size_t k = 0; k < grid.yaw.size(); ++k)
      for (size_t i = 0; i < grid.y.size(); ++i) {
        const WheelSample& s = grid.at(i, j, k);
        t.values.insert(t.values.end(), s.fields.begin(), s.fields.end());
        const double gap = std::isfinite(s.second_minimum_gap) ? s.second_minimum_gap : 1.0;
        const double jump = std::isfinite(grid.jump_distance(i, j, k)) ? grid.jump_distance(i, j, k) : 1.0;
        t.values.insert(t.values.end(), {s.valid ? 1.0 : 0.0, gap, jump});
      }
  t.num_values = static_cast<int32_t>(t.values.size());
  t.table_hash = values_hash(t.values);
  for (const auto& line : grid.line_jumps)
    for (const TreadJump& jump : line) {
      t.jump_y.push_back(jump.y);
      t.jump_roll.push_back(jump.roll);
      t.jump_yaw.push_back(jump.yaw);
    }
  t.num_jumps = static_cast<int32_t>(t.jump_y.size());
  t.file_size = 0;
  return t;
}

geometry_table_t write_table_file(const geometry_table_t& table, const std::string& path) {
  return table_reference_to(table, path, write_message_file(table, path, kTableFile));
}

geometry_table_t table_reference(const geometry_table_t& full, const std::string& path) {
  return table_reference_to(full, path, read_message_file_bytes(path, kTableFile));
}

geometry_table_t read_table_file(const std::string& path) {
  return decode_bytes<geometry_table_t>(read_message_file_bytes(path, kTableFile), path, kTableFile);
}

geometry_table_t resolve_table(const geometry_table_t& reference) {
  geometry_table_t full =
      reference.file_path.empty()
          ? reference
          : decode_bytes<geometry_table_t>(checked_file(reference, kTableFile), reference.file_path, kTableFile);
  const std::int64_t expected = static_cast<std::int64_t>(full.y_count) * full.roll_count * full.yaw_count * full.num_columns;
  if (full.version != kGeometryTableVersion || full.num_values != expected ||
      full.values.size() != static_cast<size_t>(expected) || full.column_names.size() != static_cast<size_t>(full.num_columns))
    throw std::runtime_error("geometry table " + full.model_key.substr(0, 12) + ": version " +
                             std::to_string(full.version) + ", " + std::to_string(full.values.size()) +
                             " values for a " + std::to_string(full.y_count) + " x " + std::to_string(full.roll_count) +
                             " x " + std::to_string(full.yaw_count) + " x " + std::to_string(full.num_columns) + " table");
  if (values_hash(full.values) != full.table_hash)
    throw std::runtime_error("geometry table " + full.model_key.substr(0, 12) + ": the values do not hash to table_hash");
  if (!reference.file_path.empty() && (full.model_key != reference.model_key || full.wheel != reference.wheel))
    throw std::runtime_error(std::string(kTableFile) + " " + reference.file_path + " holds another table");
  full.header = reference.header;
  full.request_id = reference.request_id;
  return full;
}
}  // namespace wrc::protocol
