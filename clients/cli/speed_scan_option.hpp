// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A scan of forward speeds on the command line, FROM:TO:STEP [m/s] (`wrc stability --speeds`,
/// `wrc sweep --critical-speeds`), through the stability library's checks.

#include <string>
#include <vector>

namespace wrc::cli {

/// The speeds FROM, FROM + STEP, ... up to TO [m/s] of text "FROM:TO:STEP"; option names the
/// option in errors. @throws UsageError naming the option and the bad text or value.
std::vector<double> parse_speed_scan(const std::string& text, const std::string& option);

}  // namespace wrc::cli
