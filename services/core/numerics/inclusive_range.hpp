// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The inclusive range FROM:TO:STEP, the one rule for every option and grid that takes one (the
/// CLI's --y-from/--y-to/--y-step, `--speeds`, a sweep's grid axis): from, from + step, ... up to
/// to, to included when the steps reach it within 1e-9 of a step, so that rounding in the decimal
/// values given does not drop the last one (0.1:0.3:0.1 has three values).

#include <vector>

namespace wrc {

/// How many values the range holds [-], >= 1.
/// @throws std::invalid_argument naming the range when from, to or step is not finite, step <= 0
///         or to < from.
long inclusive_range_count(double from, double to, double step);

/// The values [the unit of from]: from + i step for i = 0 .. inclusive_range_count() - 1, the
/// last no larger than to. @throws as inclusive_range_count().
std::vector<double> inclusive_range(double from, double to, double step);

}  // namespace wrc
