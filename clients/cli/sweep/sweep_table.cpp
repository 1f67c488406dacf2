// SPDX-License-Identifier: Apache-2.0
#include "cli/sweep/sweep_table.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wrc::sweep {
namespace {

constexpr const char* kPointColumn = "point [-]";
constexpr const char* kStatusColumn = "status [-]";
constexpr const char* kErrorColumn = "error [-]";

// The index of column in header, or header.size().
std::size_t column_of(const std::vector<std::string>& header, const std::string& column) {
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), column) - header.begin());
}

// A whole non-negative number of text, or false.
bool read_index(const std::string& text, std::size_t& value) {
  if (text.empty() || text.size() > 18 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  value = static_cast<std::size_t>(std::stoull(text));
  return true;
}

}  // namespace

std::string csv_field(const std::string& field) {
  std::string text = field;
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  const bool quote = text.find_first_of(",\"") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_record(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + csv_field(fields[i]);
  return line;
}

std::vector<std::string> split_csv_record(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::size_t i = 0;
  while (true) {
    field.clear();
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) throw std::invalid_argument("a quoted field is not closed");
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += line[i++];
      }
      if (i < line.size() && line[i] != ',') throw std::invalid_argument("text after a closing quote");
    } else {
      while (i < line.size() && line[i] != ',') {
        if (line[i] == '"') throw std::invalid_argument("a quote inside an unquoted field");
        field += line[i++];
      }
    }
    fields.push_back(field);
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return fields;
}

std::string csv_text(const CsvTable& table) {
  std::string text = csv_record(table.header) + "\n";
  for (const auto& row : table.rows) text += csv_record(row) + "\n";
  return text;
}

CsvTable parse_csv_text(const std::string& text, const std::string& source) {
  CsvTable table;
  std::stringstream lines(text);
  std::string line;
  long number = 0;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> fields;
    try {
      fields = split_csv_record(line);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(source + " line " + std::to_string(number) + ": " + e.what());
    }
    if (table.header.empty()) {
      table.header = std::move(fields);
      continue;
    }
    if (fields.size() != table.header.size())
      throw std::invalid_argument(source + " line " + std::to_string(number) + ": " + std::to_string(fields.size()) +
                                  " fields, the header has " + std::to_string(table.header.size()));
    table.rows.push_back(std::move(fields));
  }
  if (table.header.empty()) throw std::invalid_argument(source + ": no header line");
  return table;
}

CsvTable read_csv_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_csv_text(text.str(), path);
}

void write_csv_file(const std::string& path, const CsvTable& table) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(temporary + ": cannot be written");
    out << csv_text(table);
    out.flush();
    if (!out) throw std::runtime_error(temporary + ": write error");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw std::runtime_error(path + ": cannot be replaced");
}

SweepLayout::SweepLayout(Grid grid, std::vector<std::string> key_units, std::vector<std::string> result_columns)
    : grid_(std::move(grid)), results_(result_columns.size()) {
  if (key_units.size() != grid_.axes().size())
    throw std::invalid_argument("sweep layout: " + std::to_string(key_units.size()) + " units for " +
                                std::to_string(grid_.axes().size()) + " grid keys");
  header_.push_back(kPointColumn);
  for (std::size_t k = 0; k < key_units.size(); ++k) header_.push_back(grid_.axes()[k].key + " [" + key_units[k] + "]");
  header_.push_back(kStatusColumn);
  for (const std::string& c : result_columns) header_.push_back(c);
  header_.push_back(kErrorColumn);
  header_.push_back(kWallTimeColumn);
  std::set<std::string> names;
  for (const std::string& c : header_)
    if (!names.insert(c).second) throw std::invalid_argument("sweep layout: the column " + c + " comes twice");
}

std::vector<std::string> SweepLayout::record(const SweepRow& row) const {
  if (row.results.size() != results_)
    throw std::invalid_argument("sweep row of point " + std::to_string(row.point) + ": " +
                                std::to_string(row.results.size()) + " results for " + std::to_string(results_) +
                                " result columns");
  std::vector<std::string> fields{std::to_string(row.point)};
  for (const std::string& v : grid_.point(row.point)) fields.push_back(v);
  fields.push_back(row.status);
  fields.insert(fields.end(), row.results.begin(), row.results.end());
  fields.push_back(row.error);
  fields.push_back(row.wall_time);
  return fields;
}

CsvTable SweepLayout::table(const std::map<std::size_t, SweepRow>& rows) const {
  CsvTable t;
  t.header = header_;
  for (const auto& [point, row] : rows) t.rows.push_back(record(row));
  return t;
}

std::map<std::size_t, SweepRow> SweepLayout::rows_of(const CsvTable& table, const std::string& source) const {
  if (table.header != header_) {
    std::size_t i = 0;
    while (i < table.header.size() && i < header_.size() && table.header[i] == header_[i]) ++i;
    const std::string theirs = i < table.header.size() ? "'" + table.header[i] + "'" : "no column";
    const std::string ours = i < header_.size() ? "'" + header_[i] + "'" : "no column";
    throw std::invalid_argument(source + " is the CSV of another sweep: its column " + std::to_string(i + 1) + " is " +
                                theirs + " where this sweep has " + ours +
                                " (same grid keys, units and --extract to resume; or another --out)");
  }
  const std::size_t keys = grid_.axes().size();
  std::map<std::size_t, SweepRow> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::vector<std::string>& f = table.rows[r];
    const std::string where = source + " row " + std::to_string(r + 1);
    const std::vector<std::string> values(f.begin() + 1, f.begin() + 1 + static_cast<long>(keys));
    const std::size_t point = grid_.index_of(values);
    if (point == grid_.size()) {
      std::string text;
      for (std::size_t k = 0; k < keys; ++k) text += (k ? ", " : "") + grid_.axes()[k].key + " = " + values[k];
      throw std::invalid_argument(where + ": " + text + " is no point of this sweep's grid (a CSV of another sweep?)");
    }
    std::size_t written = 0;
    if (!read_index(f[0], written) || written != point)
      throw std::invalid_argument(where + ": point " + f[0] + " where this grid has its values at point " +
                                  std::to_string(point) + " (another order of the keys or values?)");
    if (rows.count(point)) throw std::invalid_argument(where + ": point " + f[0] + " comes twice");
    SweepRow row;
    row.point = point;
    row.status = f[1 + keys];
    row.results.assign(f.begin() + 2 + static_cast<long>(keys), f.end() - 2);
    row.error = f[f.size() - 2];
    row.wall_time = f.back();
    rows.emplace(point, std::move(row));
  }
  return rows;
}

std::vector<std::string> compare_sweep_tables(const CsvTable& a, const CsvTable& b, std::size_t max_reported) {
  std::vector<std::string> out;
  if (a.header != b.header) {
    out.push_back("the headers differ: " + csv_record(a.header) + " / " + csv_record(b.header));
    return out;
  }
  const std::size_t wall = column_of(a.header, kWallTimeColumn);
  auto by_first = [](const CsvTable& t) {
    std::map<std::string, const std::vector<std::string>*> m;
    for (const auto& row : t.rows) m[row.at(0)] = &row;
    return m;
  };
  const auto ra = by_first(a);
  const auto rb = by_first(b);
  auto report = [&](const std::string& what) {
    if (out.size() < max_reported) out.push_back(what);
  };
  for (const auto& [key, row] : ra) {
    const auto other = rb.find(key);
    if (other == rb.end()) {
      report(a.header[0] + " " + key + ": only in the first");
      continue;
    }
    for (std::size_t c = 0; c < row->size(); ++c)
      if (c != wall && (*row)[c] != (*other->second)[c])
        report(a.header[0] + " " + key + ", " + a.header[c] + ": " + (*row)[c] + " / " + (*other->second)[c]);
  }
  for (const auto& [key, row] : rb)
    if (!ra.count(key)) report(a.header[0] + " " + key + ": only in the second");
  return out;
}

}  // namespace wrc::sweep
