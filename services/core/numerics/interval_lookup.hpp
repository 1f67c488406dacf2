// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Finding the interval of a sorted knot sequence that holds x, in constant time for knots that are
/// roughly evenly spread (the piecewise polynomials of core/numerics evaluate through it).

#include <cstddef>
#include <vector>

namespace wrc {

/// Index i of the interval [x_i, x_{i+1}) holding x, for strictly increasing knots x_0..x_{n-1}
/// (n >= 2), clamped to the first and last interval (x < x_0: 0; x >= x_{n-1}: n - 2). A uniform
/// cell table (4 cells per knot) gives the interval at the cell's left edge; a short forward scan
/// over the knots inside the cell ends the search. No allocation when looking up.
class IntervalLookup {
 public:
  IntervalLookup() = default;
  /// @param knots strictly increasing, at least 2 (the caller checks; the lookup keeps no copy,
  ///        find() takes the same sequence).
  explicit IntervalLookup(const std::vector<double>& knots) {
    const std::size_t n = knots.size();
    const std::size_t cells = 4 * n;
    cell_scale_ = static_cast<double>(cells) / (knots[n - 1] - knots[0]);
    cell_start_.resize(cells + 1);
    std::size_t interval = 0;
    for (std::size_t k = 0; k <= cells; ++k) {
      const double left = knots[0] + static_cast<double>(k) / cell_scale_;
      while (interval + 2 < n && knots[interval + 1] <= left) ++interval;
      cell_start_[k] = static_cast<unsigned>(interval);
    }
  }

  /// The interval of x among knots (the sequence given to the constructor).
  std::size_t find(const std::vector<double>& knots, double x) const {
    const double position = (x - knots[0]) * cell_scale_;
    if (!(position > 0.0)) return 0;
    const std::size_t last_cell = cell_start_.size() - 1;
    const std::size_t cell = position < static_cast<double>(last_cell) ? static_cast<std::size_t>(position) : last_cell;
    std::size_t i = cell_start_[cell];
    const std::size_t last_interval = knots.size() - 2;
    while (i < last_interval && knots[i + 1] <= x) ++i;
    return i;
  }

 private:
  double cell_scale_ = 0;
  std::vector<unsigned> cell_start_;
};

}  // namespace wrc
