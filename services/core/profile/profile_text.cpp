#include "core/profile/profile_text.hpp"

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>

#include <sys/stat.h>

#include "core/numerics/number_text.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {
namespace profile_text {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n\f\v");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n\f\v");
  return text.substr(first, last - first + 1);
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::vector<std::string> split_fields(const std::string& text) {
  std::vector<std::string> fields;
  std::string current;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == ';') {
      if (!current.empty()) fields.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) fields.push_back(current);
  return fields;
}

bool parse_number(const std::string& token, double& value) {
  const std::optional<double> number = whole_number(token);
  if (number) value = *number;
  return number.has_value();
}

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<std::string> read_lines(const std::string& path) {
  // stat first: opening a FIFO would block, and a device (/dev/urandom) never ends.
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw ProfileError(path, 0, "cannot open file");
  if (!S_ISREG(info.st_mode)) {
    const char* kind = S_ISDIR(info.st_mode)    ? "a directory"
                       : S_ISFIFO(info.st_mode) ? "a FIFO"
                       : S_ISCHR(info.st_mode)  ? "a character device"
                       : S_ISBLK(info.st_mode)  ? "a block device"
                       : S_ISSOCK(info.st_mode) ? "a socket"
                                                : "not a plain file";
    throw ProfileError(path, 0, std::string("not a regular file (") + kind + ")");
  }
  const auto too_large = [&](std::uintmax_t bytes) {
    return ProfileError(path, 0, "file too large: " + std::to_string(bytes) + " bytes (at most " +
                                     std::to_string(kMaxProfileFileBytes) + ")");
  };
  if (static_cast<std::uintmax_t>(info.st_size) > kMaxProfileFileBytes) throw too_large(info.st_size);
  std::ifstream in(path);
  if (!in) throw ProfileError(path, 0, "cannot open file");
  std::vector<std::string> lines;
  std::string line;
  std::size_t bytes = 0;
  while (std::getline(in, line)) {
    bytes += line.size() + 1;
    if (bytes > kMaxProfileFileBytes) throw too_large(bytes);  // it grew since stat
    lines.push_back(line);
  }
  return lines;
}

}  // namespace profile_text
}  // namespace wrc
