// SPDX-License-Identifier: Apache-2.0
#include "core/profile/profile_text.hpp"

#include <cctype>
#include <cstdlib>

#include "core/numerics/number_text.hpp"
#include "core/profile/profile_file_bytes.hpp"

namespace wrc {
namespace profile_text {

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
  // Lines as std::getline gives them: split at '\n', no empty line after a final '\n'.
  const std::string bytes = read_profile_file_bytes(path);
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < bytes.size()) {
    const std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(bytes.substr(start));
      break;
    }
    lines.push_back(bytes.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

}  // namespace profile_text
}  // namespace wrc
