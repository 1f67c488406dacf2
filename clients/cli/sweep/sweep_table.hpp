// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The CSV of a sweep: one row per run, in grid order, and reading it back to resume. Columns:
/// "point [-]" (the run's index in the grid), one per grid key ("speed [m/s]", its unit the
/// caller's), "status [-]" (finished, failed, stopped), the extracted results, "error [-]" (why a
/// run failed, empty otherwise) and "wall_time [s]" last, the only column that differs between two
/// sweeps of the same grid (compare_sweep_tables() leaves it out). Fields with a comma, a quote or
/// leading or trailing spaces are quoted (RFC 4180), line breaks inside a field become spaces, so
/// every record is one line. No LCM.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "cli/sweep/sweep_grid.hpp"

namespace wrc::sweep {

/// The name of the column compare_sweep_tables() ignores.
inline constexpr const char* kWallTimeColumn = "wall_time [s]";

/// A CSV file as text fields: the header and the records.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// field as a CSV field (quoted when needed).
std::string csv_field(const std::string& field);
/// One record of fields as one line, without the line break.
std::string csv_record(const std::vector<std::string>& fields);
/// The fields of one line. @throws std::invalid_argument for an unbalanced quote or text after a
/// closing quote.
std::vector<std::string> split_csv_record(const std::string& line);

/// The table in text (header first, "\n" after every record).
std::string csv_text(const CsvTable& table);
/// The table of text; source names it in errors ("FILE line N: ..."). A record with another
/// number of fields than the header is refused.
/// @throws std::invalid_argument.
CsvTable parse_csv_text(const std::string& text, const std::string& source);

/// Reads path. @throws std::runtime_error when it cannot be read, std::invalid_argument as parse_csv_text.
CsvTable read_csv_file(const std::string& path);
/// Writes the table to path.tmp and renames it to path, so an interrupted write never leaves a
/// partial CSV. @throws std::runtime_error naming the path.
void write_csv_file(const std::string& path, const CsvTable& table);

/// The result of one run of the grid.
struct SweepRow {
  std::size_t point = 0;             ///< index in the grid
  std::string status;                ///< finished, failed or stopped
  std::vector<std::string> results;  ///< one per result column, as text ("" for none)
  std::string error;                 ///< why the run failed, "" when it did not
  std::string wall_time;             ///< [s], as text
};

/// The columns of a sweep: the grid's keys with their units, and the result columns (each
/// "name [unit]").
class SweepLayout {
 public:
  /// key_units: one unit per axis of grid ("m/s", "-"). @throws std::invalid_argument when the
  /// counts differ or a column name is repeated.
  SweepLayout(Grid grid, std::vector<std::string> key_units, std::vector<std::string> result_columns);

  const Grid& grid() const { return grid_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t result_count() const { return results_; }

  /// The record of row: its point, the grid values there, status, results, error, wall time.
  /// @throws std::invalid_argument when row has another number of results than the layout.
  std::vector<std::string> record(const SweepRow& row) const;

  /// The table of rows, sorted by point.
  CsvTable table(const std::map<std::size_t, SweepRow>& rows) const;

  /// The rows of an existing sweep CSV, by point, to resume it. source names it in errors.
  /// @throws std::invalid_argument when the header is another sweep's (naming the first column
  /// that differs), a row's values are no point of this grid or disagree with its point column,
  /// or a point comes twice.
  std::map<std::size_t, SweepRow> rows_of(const CsvTable& table, const std::string& source) const;

 private:
  Grid grid_;
  std::vector<std::string> header_;
  std::size_t results_ = 0;
};

/// The differences between two sweep tables, every column but kWallTimeColumn: a header that
/// differs, rows missing on either side, and each field that differs ("point 3, status [-]:
/// finished / failed"), at most max_reported of them; empty when they are the same.
std::vector<std::string> compare_sweep_tables(const CsvTable& a, const CsvTable& b, std::size_t max_reported = 20);

}  // namespace wrc::sweep
