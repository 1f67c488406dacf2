// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/parameter_table.hpp"

#include <cmath>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

std::string end_text(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return number_text(value, 9);
}

}  // namespace

bool ParameterRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above = lower == Bound::kClosed ? value >= min : value > min;
  const bool below = upper == Bound::kClosed ? value <= max : value < max;
  return above && below;
}

std::string ParameterRange::text() const {
  return std::string(lower == Bound::kClosed ? "[" : "(") + end_text(min) + ", " + end_text(max) +
         (upper == Bound::kClosed ? "]" : ")");
}

std::string ParameterInfo::option_name() const {
  if (option) return option;
  std::string name = std::string("--") + key;
  for (char& c : name)
    if (c == '_') c = '-';
  return name;
}

std::optional<std::string> ParameterInfo::violation(double value) const {
  if (kind == ParameterKind::kBoolean)
    return value == 0.0 || value == 1.0 ? std::nullopt : std::optional<std::string>("is not true or false");
  if (kind == ParameterKind::kInteger && std::isfinite(value) && value != std::floor(value))
    return "is not a whole number";
  if (!range.contains(value)) return "is outside " + range.text() + " [" + unit + "]";
  return std::nullopt;
}

std::string ParameterInfo::value_text(double value) const {
  if (kind == ParameterKind::kBoolean) return value != 0.0 ? "true" : "false";
  if (kind == ParameterKind::kInteger && std::isfinite(value) && std::abs(value) < 9e15)
    return std::to_string(static_cast<long long>(value));
  return shortest_number_text(value);
}

double ParameterInfo::parse(const std::string& text, const std::string& what) const {
  if (parse_text) {
    try {
      return parse_text(text);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + ": " + e.what());
    }
  }
  if (kind == ParameterKind::kBoolean) {
    if (text == "true") return 1.0;
    if (text == "false") return 0.0;
    throw std::invalid_argument(what + ": '" + text + "' is not true or false");
  }
  const double value = parse_finite_number(text, what);
  // A whole number too large for its parameter is outside the range (violation()), not "not whole".
  if (kind == ParameterKind::kInteger && value != std::floor(value))
    throw std::invalid_argument(what + ": '" + text + "' is not a whole number");
  return value;
}

std::string parameter_error(const ParameterInfo& parameter, double value, const std::string& violation) {
  return std::string(parameter.key) + " = " + number_text(value, 9) + " " + violation;
}

}  // namespace wrc
