// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Launch profiles: which service processes `wrc launch` starts. A profile is a text file with
/// one service per line, `name executable [arguments...]`, separated by blanks (no quoting);
/// `#` starts a comment. The executable is a program name looked up in the build tree
/// (see find_service_executable) or a path containing '/'.

#include <string>
#include <vector>

namespace wrc::bus {

/// One service of a launch profile.
struct LaunchEntry {
  std::string name;               ///< unique name in the profile, e.g. "contact-onepoint"
  std::string executable;         ///< program name ("wrc-contactd") or path
  std::vector<std::string> args;  ///< arguments after the executable
  int line = 0;                   ///< line number in the profile (for messages)
};

/// Parses profile text; source names the file in error messages. Throws std::invalid_argument
/// "<source>:<line>: ..." for a line with a name but no executable or a duplicate name.
std::vector<LaunchEntry> parse_launch_profile(const std::string& text, const std::string& source);

/// Reads and parses a profile file; throws std::runtime_error naming the file if unreadable.
std::vector<LaunchEntry> read_launch_profile(const std::string& path);

/// The entries named in `names` in the order given, or all entries when names is empty.
/// Throws std::invalid_argument naming an unknown service and listing the known ones.
std::vector<LaunchEntry> select_services(const std::vector<LaunchEntry>& profile,
                                         const std::vector<std::string>& names);

}  // namespace wrc::bus
