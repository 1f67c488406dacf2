// SPDX-License-Identifier: Apache-2.0
#include "bus/auth/bus_key.hpp"

#include <fcntl.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace wrc::bus {

namespace {

constexpr std::size_t kFileLimit = 256;  // [B] far more than 64 hex digits and a newline

std::string env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::string(value) : std::string();
}

std::string octal_mode(mode_t mode) {
  std::ostringstream out;
  out << "0" << std::oct << (mode & 07777);
  return out.str();
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string to_hex(const BusKey& key) {
  static const char digits[] = "0123456789abcdef";
  std::string out;
  for (std::uint8_t b : key.bytes) {
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  return out;
}

BusKey parse_key(const std::string& path, std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  if (text.size() != 2 * BusKey::kBytes) {
    throw std::runtime_error("bus key " + path + ": expected 64 hex digits, found " + std::to_string(text.size()) +
                             " characters");
  }
  BusKey key;
  for (std::size_t i = 0; i < BusKey::kBytes; ++i) {
    const int hi = hex_value(text[2 * i]);
    const int lo = hex_value(text[2 * i + 1]);
    if (hi < 0 || lo < 0) {
      throw std::runtime_error("bus key " + path + ": character " + std::to_string(2 * i + (hi < 0 ? 1 : 2)) +
                               " is not a hex digit");
    }
    key.bytes[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  return key;
}

}  // namespace

std::string bus_key_path(const std::string& option) {
  if (!option.empty()) return option;
  if (std::string path = env("WRC_BUS_KEY"); !path.empty()) return path;
  if (std::string config = env("XDG_CONFIG_HOME"); !config.empty()) return config + "/wrc/bus.key";
  if (std::string home = env("HOME"); !home.empty()) return home + "/.config/wrc/bus.key";
  throw std::runtime_error("no place for the bus key: set --bus-key, WRC_BUS_KEY, XDG_CONFIG_HOME or HOME");
}

BusKey read_bus_key(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) {
      throw std::runtime_error("no bus key at " + path +
                               " (`wrc launch` creates one; for several machines copy the key file of the first)");
    }
    throw std::runtime_error("cannot open bus key " + path + ": " + std::strerror(error));
  }
  struct stat st {};
  std::string text;
  std::string problem;
  if (::fstat(fd, &st) != 0) {
    problem = std::string("cannot stat: ") + std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    problem = "not a regular file";
  } else if (st.st_uid != ::geteuid()) {
    problem = "owned by uid " + std::to_string(st.st_uid) + ", not by this user (uid " +
              std::to_string(::geteuid()) + ")";
  } else if ((st.st_mode & 077) != 0) {
    problem = "mode " + octal_mode(st.st_mode) + " lets group or others at it (chmod 600 " + path + ")";
  } else if (st.st_size > static_cast<off_t>(kFileLimit)) {
    problem = "is " + std::to_string(st.st_size) + " bytes, a key file has 65";
  } else {
    char buf[kFileLimit + 1];
    const ssize_t n = ::read(fd, buf, kFileLimit);
    if (n < 0) problem = std::string("cannot read: ") + std::strerror(errno);
    else text.assign(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  if (!problem.empty()) throw std::runtime_error("bus key " + path + ": " + problem);
  return parse_key(path, text);
}

BusKey read_or_create_bus_key(const std::string& path, bool* created) {
  if (created != nullptr) *created = false;
  const std::filesystem::path file(path);
  if (file.has_parent_path() && !std::filesystem::exists(file.parent_path())) {
    std::filesystem::create_directories(file.parent_path());
    std::filesystem::permissions(file.parent_path(), std::filesystem::perms::owner_all);
  }
  // Written completely under a temporary name, then linked to the final name: link() fails when
  // the name exists, so two launchers starting at once agree on one key and nobody reads half a file.
  const std::string temporary = path + ".new." + std::to_string(::getpid());
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) throw std::runtime_error("cannot create bus key " + path + ": " + std::strerror(errno));
  BusKey key;
  bool written = RAND_bytes(key.bytes.data(), static_cast<int>(key.bytes.size())) == 1;
  const std::string text = to_hex(key) + "\n";
  written = written && ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && ::fsync(fd) == 0;
  ::close(fd);
  if (!written) {
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot write bus key " + path + " (random generator or disk failed)");
  }
  const int linked = ::link(temporary.c_str(), path.c_str());
  const int link_error = errno;
  ::unlink(temporary.c_str());
  if (linked != 0) {
    if (link_error == EEXIST) return read_bus_key(path);
    throw std::runtime_error("cannot create bus key " + path + ": " + std::strerror(link_error));
  }
  if (created != nullptr) *created = true;
  return key;
}

}  // namespace wrc::bus
