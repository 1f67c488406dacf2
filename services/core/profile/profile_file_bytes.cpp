#include "core/profile/profile_file_bytes.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/profile/profile_error.hpp"
#include "core/profile/profile_limits.hpp"

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

std::string read_profile_file_bytes(const std::string& path) {
  // O_NONBLOCK: opening a FIFO without a writer would block; the kind is then checked on the
  // descriptor itself, so nothing can swap the file between the check and the read.
  Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw ProfileError(path, 0, std::string("cannot open file (") + std::strerror(errno) + ")");
  struct stat info {};
  if (::fstat(file.fd, &info) != 0)
    throw ProfileError(path, 0, std::string("cannot open file (") + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode)) throw ProfileError(path, 0, std::string("not a regular file (") + file_kind(info.st_mode) + ")");
  const auto too_large = [&](unsigned long long bytes) {
    return ProfileError(path, 0, "file too large: " + std::to_string(bytes) + " bytes (at most " +
                                     std::to_string(kMaxProfileFileBytes) + ")");
  };
  if (static_cast<unsigned long long>(info.st_size) > kMaxProfileFileBytes) throw too_large(info.st_size);
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(info.st_size));
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw ProfileError(path, 0, std::string("read error (") + std::strerror(errno) + ")");
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > kMaxProfileFileBytes) throw too_large(bytes.size());  // it grew since fstat
  }
  return bytes;
}

}  // namespace wrc
