#pragma once
/// @file
/// Where the build tree and the source tree are, for programs that start other programs
/// (`wrc launch`, `wrc spy`).

#include <optional>
#include <string>

namespace wrc::bus {

/// The build directory: $WRC_BUILD_DIR when set, else the directory two levels above this
/// executable (wrc-cli lives in <build>/clients/).
std::string build_dir();

/// The source directory: $WRC_ROOT when set, else CMAKE_HOME_DIRECTORY from the build's
/// CMakeCache.txt; empty when neither is known.
std::string source_dir();

/// Finds a service executable: a name containing '/' is used as is; otherwise
/// <build>/services/<name without "wrc-">/<name>, then <build>/services/*/<name>.
/// Returns nothing when no executable file exists.
std::optional<std::string> find_service_executable(const std::string& name, const std::string& build);

}  // namespace wrc::bus
