// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The front end's names for the one option parser of wrc (options/options.hpp), shared with
/// every service.

#include "core/numerics/inclusive_range.hpp"
#include "options/options.hpp"

namespace wrc::cli {
using wrc::OptionSpec;
using wrc::Options;
using wrc::parse_finite;
using wrc::Positional;
using wrc::UsageError;

/// Values from, from + step, ... up to to inclusive (a range option's --X-from, --X-to, --X-step):
/// how many there are [-], by the one rule of core/numerics/inclusive_range.hpp. Needs step > 0
/// and to >= from (the callers check them first, naming their options).
inline long inclusive_step_count(double from, double to, double step) { return inclusive_range_count(from, to, step); }

}  // namespace wrc::cli
