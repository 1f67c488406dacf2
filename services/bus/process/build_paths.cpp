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
  return {};
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
  return std::nullopt;
}

}  // namespace wrc::bus
