// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The FASTSIM grid option of the front end (--grid MxN: elements per strip x strips), for the
/// commands that compute creep forces (wrc creep, wrc query), each within its own limits.

#include <string>

#include "cli/options.hpp"

namespace wrc::cli {

/// A FASTSIM grid: elements per strip along the rolling direction x strips across it [-].
struct FastsimGrid {
  int elements_per_strip = 0;
  int strips = 0;
};

/// The option's spec: --grid, its help and the library's default grid (core/contact/fastsim.hpp:
/// kDefaultFastsimGrid) as "MxN".
OptionSpec grid_option_spec();

/// text as "MxN" (x or X), each a whole number in min..max.
/// @throws UsageError "--grid: '<text>' is not MxN with whole numbers in <min>..<max> (e.g. 20x20)".
FastsimGrid parse_grid(const std::string& text, int min, int max);

/// The grid --grid gives (parse_grid within min..max), the library's default when absent.
FastsimGrid grid_option(const Options& options, int min, int max);

}  // namespace wrc::cli
