// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Small text helpers shared by the profile file readers (internal to the profile module).

#include <string>
#include <vector>

#include "core/numerics/trim.hpp"

namespace wrc {
namespace profile_text {

/// The string without leading and trailing white space (core/numerics/trim.hpp).
using ::wrc::trim;

/// Lower-case copy (ASCII).
std::string lower(std::string text);

/// Splits at white space, commas and semicolons; empty fields between separators are dropped.
std::vector<std::string> split_fields(const std::string& text);

/// Parses a whole token as a double (strtod; "nan" and "inf" parse and are caught later by the
/// point validation). Returns false if the token is not entirely one number.
bool parse_number(const std::string& token, double& value);

/// The final path component, for profile names.
std::string base_name(const std::string& path);

/// All lines of a profile file, read by the one profile file rule (profile_file_bytes.hpp).
/// @throws ProfileError(path, 0, reason) as read_profile_file_bytes does.
std::vector<std::string> read_lines(const std::string& path);

}  // namespace profile_text
}  // namespace wrc
