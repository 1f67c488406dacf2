// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The front end's names for the one option parser of wrc (options/options.hpp), shared with
/// every service.

#include "options/options.hpp"

namespace wrc::cli {
using wrc::OptionSpec;
using wrc::Options;
using wrc::parse_finite;
using wrc::Positional;
using wrc::UsageError;

}  // namespace wrc::cli
