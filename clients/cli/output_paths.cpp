// SPDX-License-Identifier: Apache-2.0
#include "cli/output_paths.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "cli/options.hpp"

namespace wrc::cli {
namespace {

// The folder path is in ("." for a bare name).
std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// Why path's folder cannot hold a new file, or "" when it exists as a folder.
std::string folder_problem(const std::string& folder) {
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) return "the folder " + folder + " does not exist";
  if (!S_ISDIR(st.st_mode)) return folder + " is not a folder";
  return "";
}

}  // namespace

void check_output_path(const std::string& path, const std::string& what) {
  const std::string name = what + " " + path;
  if (path.empty()) throw UsageError(what + ": empty file name");
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw UsageError(name + ": is a directory");
    // An existing file: open it for writing without truncating it (O_NONBLOCK: a FIFO without a
    // reader fails instead of waiting).
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) throw UsageError(name + ": cannot be written: " + std::strerror(errno));
    ::close(fd);
    return;
  }
  // A new file: create it and remove it again.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, 0644);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT || error == ENOTDIR) {
      const std::string problem = folder_problem(folder_of(path));
      if (!problem.empty()) throw UsageError(name + ": " + problem);
    }
    throw UsageError(name + ": cannot be written: " + std::strerror(error));
  }
  ::close(fd);
  ::unlink(path.c_str());
}

}  // namespace wrc::cli
