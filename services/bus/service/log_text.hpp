// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Strings from messages as a service's log shows them: a run id, a model name or a reason from
/// another process must not forge a log line (a newline), move the terminal (an escape sequence)
/// or fill the log (a string of many kilobytes).

#include <cstddef>
#include <string>
#include <string_view>

namespace wrc::bus {

/// Longest part of a string a log line shows [B].
inline constexpr std::size_t kMaxLogText = 120;

/// text with printable ASCII as it is, a backslash as "\\" and every other byte as "\xHH"; of a
/// text longer than max_bytes [B] the first max_bytes, then "... (N bytes)".
std::string log_text(std::string_view text, std::size_t max_bytes = kMaxLogText);

}  // namespace wrc::bus
