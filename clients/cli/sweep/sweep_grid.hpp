// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The grid of a parameter sweep (`wrc sweep --grid KEY=VALUES`): per key its values, as text
/// exactly as each run gets them, and the runs as the Cartesian product in one fixed order (the
/// first key varies slowest), numbered from 0. The values are lists and ranges: "0.2,0.3,0.4",
/// "10:40:10" (from 10 to 40 every 10, both ends included within rounding), or both
/// ("10:30:10,35"); any other item is one value of its own ("conic:0.05", "profiles/a.txt").
/// What a key means and which values are valid is the caller's (the run options); here only the
/// form. No LCM, no files.

#include <cstddef>
#include <string>
#include <vector>

namespace wrc::sweep {

/// Most values one key may have [-].
inline constexpr std::size_t kMaxAxisValues = 10000;
/// Most runs one grid may have [-].
inline constexpr std::size_t kMaxGridPoints = 100000;

/// One key and its values, in the order given.
struct GridAxis {
  std::string key;
  std::vector<std::string> values;
};

/// "KEY=VALUES" as an axis. A key is letters, digits, '_' and '-' (a '-' stands for '_': the key
/// of the option --vertical-force is vertical_force); values are split at ',', a FROM:TO:STEP item
/// (three numbers) is expanded, empty items are refused and so are repeated values.
/// @throws std::invalid_argument naming the text and what is wrong with it.
GridAxis parse_grid_axis(const std::string& text);

/// The values of the range FROM:TO:STEP: from, from + step, ... up to to (included when within
/// 1e-9 steps of it), each written as the shortest text of the value rounded to 12 significant
/// digits (10:40:10 gives 10, 20, 30, 40; 0.1:0.3:0.1 gives 0.1, 0.2, 0.3).
/// @throws std::invalid_argument for values that are not finite, step <= 0, to < from, or more than
/// kMaxAxisValues values.
std::vector<std::string> range_values(double from, double to, double step);

/// The runs of the axes: the Cartesian product, the first axis varying slowest.
class Grid {
 public:
  Grid() = default;
  /// @throws std::invalid_argument for no axis, an axis without values, a key given twice, or
  /// more than kMaxGridPoints runs.
  explicit Grid(std::vector<GridAxis> axes);

  const std::vector<GridAxis>& axes() const { return axes_; }
  /// Number of runs [-].
  std::size_t size() const { return size_; }
  /// The value of every axis at run index (axis order). @throws std::out_of_range past size().
  std::vector<std::string> point(std::size_t index) const;
  /// The index of the run with these values (axis order), or size() when there is none.
  std::size_t index_of(const std::vector<std::string>& values) const;

 private:
  std::vector<GridAxis> axes_;
  std::size_t size_ = 0;
};

}  // namespace wrc::sweep
