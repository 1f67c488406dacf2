// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Log files of started services removed when the command is ended by a signal (Ctrl-C, kill), so
/// an interrupted command leaves nothing behind in the temporary directory.

#include <string>

namespace wrc::cli {

/// Registers path for removal should the process end by SIGINT, SIGTERM, SIGHUP or SIGQUIT; the
/// first registration installs the handler for each of these signals whose disposition is still
/// the default (a command's own shutdown handler is left alone). The handler removes every
/// registered file and ends the process by the same signal. At most kMaxRemovedOnSignal paths of
/// fewer than 1024 characters; others are silently not registered.
void remove_on_signal(const std::string& path);

/// Unregisters path (a normal end decides itself whether to keep the log).
void keep_on_signal(const std::string& path);

/// How many paths remove_on_signal() holds at once.
inline constexpr int kMaxRemovedOnSignal = 8;

}  // namespace wrc::cli
