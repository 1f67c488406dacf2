#pragma once
/// @file
/// The front end's names for the one option parser of wrc (options/options.hpp), shared with
/// every service.

#include <cmath>

#include "options/options.hpp"

namespace wrc::cli {
using wrc::OptionSpec;
using wrc::Options;
using wrc::parse_finite;
using wrc::Positional;
using wrc::UsageError;

/// Values from, from + step, ... up to to inclusive (a range option's --X-from, --X-to, --X-step):
/// how many there are [-]. A to that the steps reach within 1e-9 of a step counts, so rounding in
/// the options' decimal values does not drop the last one. Needs step > 0 and to >= from.
inline long inclusive_step_count(double from, double to, double step) {
  return std::lround(std::floor((to - from) / step + 1e-9)) + 1;
}

}  // namespace wrc::cli
