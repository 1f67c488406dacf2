// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/message_file.hpp"

#include <iterator>

namespace wrc::protocol {

std::vector<char> read_message_file_bytes(const std::string& path, const char* what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error(std::string(what) + " " + path + " is missing");
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(std::string(what) + " " + path + ": read error");
  return bytes;
}
}  // namespace wrc::protocol
