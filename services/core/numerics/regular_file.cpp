// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/regular_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace wrc {
namespace {

const char* file_kind(mode_t mode) {
  return S_ISDIR(mode)    ? "a directory"
         : S_ISFIFO(mode) ? "a FIFO"
         : S_ISCHR(mode)  ? "a character device"
         : S_ISBLK(mode)  ? "a block device"
         : S_ISSOCK(mode) ? "a socket"
                          : "not a plain file";
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_regular_file(const std::string& path, std::size_t max_bytes) {
  // O_NONBLOCK: opening a FIFO without a writer would block; the kind is then checked on the
  // descriptor itself, so nothing can swap the file between the check and the read.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw FileReadError(path, std::string("cannot open file (") + std::strerror(errno) + ")");
  struct stat info {};
  if (::fstat(file.fd, &info) != 0)
    throw FileReadError(path, std::string("cannot open file (") + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode)) throw FileReadError(path, std::string("not a regular file (") + file_kind(info.st_mode) + ")");
  const auto too_large = [&](unsigned long long bytes) {
    return FileReadError(path, "file too large: " + std::to_string(bytes) + " bytes (at most " +
                                   std::to_string(max_bytes) + ")");
  };
  if (static_cast<unsigned long long>(info.st_size) > max_bytes) throw too_large(info.st_size);
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw FileReadError(path, std::string("read error (") + std::strerror(errno) + ")");
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > max_bytes) throw too_large(bytes.size());  // it grew since fstat
  }
  return bytes;
}

}  // namespace wrc
