// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/number_text.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace wrc {

std::optional<double> whole_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

std::optional<double> finite_number(const std::string& text) {
  errno = 0;
  const std::optional<double> value = whole_number(text);
  if (!value || errno == ERANGE || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::string not_a_finite_number(const std::string& what, const std::string& text) {
  return what + ": '" + text + "' is not a finite number";
}

double parse_finite_number(const std::string& text, const std::string& what) {
  if (const std::optional<double> value = finite_number(text)) return *value;
  throw std::invalid_argument(not_a_finite_number(what, text));
}

std::string number_text(double value, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

std::string shortest_number_text(double value) {
  char buf[64];
  const auto written = std::to_chars(buf, buf + sizeof buf, value);  // shortest exact form
  std::string text(buf, written.ptr);
  // "1e-06" -> "1e-6", "1.5e+07" -> "1.5e7": the same number, as people write it
  if (const auto e = text.find('e'); e != std::string::npos) {
    std::string exponent = text.substr(e + 1);
    const bool negative = exponent[0] == '-';
    if (exponent[0] == '-' || exponent[0] == '+') exponent.erase(0, 1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = text.substr(0, e + 1) + (negative ? "-" : "") + exponent;
  }
  return text;
}

}  // namespace wrc
