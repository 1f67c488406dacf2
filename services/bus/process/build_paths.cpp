// SPDX-License-Identifier: Apache-2.0
#include "bus/process/build_paths.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace wrc::bus {

namespace fs = std::filesystem;

namespace {
bool is_executable_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}
}  // namespace

std::string build_dir() {
  if (const char* env = std::getenv("WRC_BUILD_DIR"); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "build";
  return self.parent_path().parent_path().string();
}

std::string source_dir() {
  if (const char* env = std::getenv("WRC_ROOT"); env != nullptr && *env != '\0') return env;
  std::ifstream cache(fs::path(build_dir()) / "CMakeCache.txt");
  const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
  for (std::string line; std::getline(cache, line);) {
    if (line.rfind(key, 0) == 0) return line.substr(key.size());
  }
  // An installed tree: the data beside bin/ (cmake/Install.cmake).
  std::error_code ec;
  if (const fs::path data = fs::path(build_dir()) / "share/wrc"; fs::is_directory(data / "profiles", ec))
    return data.string();
  return {};
}

std::string lcm_types_jar() {
  const fs::path built = fs::path(build_dir()) / "lcmtypes/wrc_lcmtypes_java.jar";
  const fs::path installed = fs::path(build_dir()) / "share/java/wrc_lcmtypes_java.jar";
  std::error_code ec;
  return (fs::exists(built, ec) || !fs::exists(installed, ec) ? built : installed).string();
}

std::optional<std::string> find_service_executable(const std::string& name, const std::string& build) {
  if (name.find('/') != std::string::npos) {
    if (is_executable_file(name)) return name;
    return std::nullopt;
  }
  std::string folder = name.rfind("wrc-", 0) == 0 ? name.substr(4) : name;
  const fs::path services = fs::path(build) / "services";
  if (const fs::path direct = services / folder / name; is_executable_file(direct)) return direct.string();
  std::error_code ec;
  for (const auto& dir : fs::directory_iterator(services, ec)) {
    if (const fs::path candidate = dir.path() / name; is_executable_file(candidate)) {
      return candidate.string();
    }
  }
  // An installed tree: the services beside the running executable (bin/).
  if (const fs::path self = fs::read_symlink("/proc/self/exe", ec); !ec) {
    if (const fs::path beside = self.parent_path() / name; is_executable_file(beside)) return beside.string();
  }
  return std::nullopt;
}

}  // namespace wrc::bus
