// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Where the build tree and the source tree are, for programs that start other programs
/// (`wrc launch`, `wrc spy`).

#include <optional>
#include <string>

namespace wrc::bus {

/// The build directory: $WRC_BUILD_DIR when set, else the directory two levels above this
/// executable (wrc-cli lives in <build>/clients/; an installed wrc in <prefix>/bin/, which makes
/// it the prefix).
std::string build_dir();

/// The source directory: $WRC_ROOT when set, else CMAKE_HOME_DIRECTORY from the build's
/// CMakeCache.txt, else, in an installed tree (no CMakeCache.txt), <prefix>/share/wrc, which
/// holds the same profiles/ and parameters/; empty when none is known.
std::string source_dir();

/// The jar of wrc's message types for lcm-spy: <build>/lcmtypes/wrc_lcmtypes_java.jar, or in an
/// installed tree <prefix>/share/java/wrc_lcmtypes_java.jar.
std::string lcm_types_jar();

/// Finds a service executable: a name containing '/' is used as is; otherwise
/// <build>/services/<name without "wrc-">/<name>, then <build>/services/*/<name>, then (an
/// installed tree) <name> beside the running executable. Returns nothing when no executable
/// file exists.
std::optional<std::string> find_service_executable(const std::string& name, const std::string& build);

}  // namespace wrc::bus
