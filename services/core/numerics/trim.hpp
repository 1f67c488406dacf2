// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// White space off both ends of a text: what every reader of a text file (profiles, track
/// irregularities) does to a line or a cell before reading it.

#include <string>

namespace wrc {

/// The text without leading and trailing white space (" \t\r\n\f\v").
std::string trim(const std::string& text);

}  // namespace wrc
