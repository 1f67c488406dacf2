// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A declarative table of one parameter set: per member its key, command-line option, unit,
/// description, kind, valid range and accessors, declared once. Everything else is generated from
/// it: the validation (validate_parameters), and, in the layers that know them, the parameter
/// file, the command-line options and their --help defaults, the message codec and the JSON
/// summary. The default of a member is the value of a default-constructed set (T{}).

#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace wrc {

/// What a parameter's value is: any number, a whole number, or true / false (as 1 / 0).
enum class ParameterKind { kNumber, kInteger, kBoolean };

/// Whether an end of a range belongs to it.
enum class Bound { kOpen, kClosed };

/// The valid values of a parameter: finite (always) and between min and max, each end open or
/// closed; an infinite end bounds nothing but finiteness.
struct ParameterRange {
  double min = -std::numeric_limits<double>::infinity();
  Bound lower = Bound::kOpen;
  double max = std::numeric_limits<double>::infinity();
  Bound upper = Bound::kOpen;

  /// True when value is finite and within the range.
  bool contains(double value) const;
  /// The range as an interval: "(0, 0.06)", "[0, 100]", "(0, inf)", "(-inf, inf)".
  std::string text() const;
};

/// Any finite value.
inline constexpr ParameterRange kAnyFinite{};
/// (0, inf): positive.
inline constexpr ParameterRange kPositive{0.0, Bound::kOpen, std::numeric_limits<double>::infinity(), Bound::kOpen};
/// [0, inf): not negative.
inline constexpr ParameterRange kNonNegative{0.0, Bound::kClosed, std::numeric_limits<double>::infinity(),
                                             Bound::kOpen};
/// (-limit, limit): |value| < limit.
inline constexpr ParameterRange below_magnitude(double limit) {
  return {-limit, Bound::kOpen, limit, Bound::kOpen};
}
/// [min, max].
inline constexpr ParameterRange closed(double min, double max) { return {min, Bound::kClosed, max, Bound::kClosed}; }

/// What describes a parameter besides its accessors (the part the generated code reads).
struct ParameterInfo {
  const char* key;          ///< name in the library's files, messages and summaries, e.g. "yaw0"
  const char* option;       ///< command-line option, e.g. "--yaw0"; nullptr: "--" + key, '_' -> '-';
                            ///< "": none of its own (set by a compound option, "--box")
  const char* unit;         ///< e.g. "rad"; "-" for none
  const char* description;  ///< one line, no unit
  ParameterKind kind = ParameterKind::kNumber;
  /// A kInteger entry's range is finite and within +-2^53 (every whole number in it exact in a
  /// double and within its member's type): a too large count is outside it, not "not a whole
  /// number" (tests/bus/unit/parameter_tables_test.cpp holds every table to it).
  ParameterRange range = kAnyFinite;
  /// The default as --help shows it when the number would not say it (the inclination's "1:40");
  /// nullptr: the value of T{}.
  const char* shown_default = nullptr;
  /// A parser of the option's text other than the number (the inclination's "1:40"); nullptr:
  /// the whole text is one number of the parameter's kind. Throws std::invalid_argument.
  double (*parse_text)(const std::string& text) = nullptr;

  /// The command-line option: option, or "--" + key with '_' written '-'.
  std::string option_name() const;
  /// False for an entry with no option of its own (option "").
  bool has_option() const { return !option || *option != '\0'; }
  /// Why value is not valid ("is outside (0, 0.1) [-]", "is not a whole number"), or nothing.
  std::optional<std::string> violation(double value) const;
  /// value as the parameter file and --help write it: true / false, a whole number, or the
  /// shortest text that reads back exactly.
  std::string value_text(double value) const;
  /// The text of an option as a value of this parameter (parse_text, or a number of the kind,
  /// booleans as true / false), not yet checked against the range.
  /// @throws std::invalid_argument "<what>: '<text>' ..." when it is none.
  double parse(const std::string& text, const std::string& what) const;
};

/// One parameter of a set T.
template <class T>
struct Parameter : ParameterInfo {
  std::function<double(const T&)> get;  ///< the value (booleans as 0 / 1)
  std::function<void(T&, double)> set;
};

/// The parameter of member m of T described by info; its kind follows from the member's type
/// (bool: kBoolean, a whole-number type: kInteger, else info's).
template <class T, class V>
Parameter<T> member_parameter(ParameterInfo info, V T::*m) {
  Parameter<T> p;
  static_cast<ParameterInfo&>(p) = info;
  if constexpr (std::is_same_v<V, bool>)
    p.kind = ParameterKind::kBoolean;
  else if constexpr (std::is_integral_v<V>)
    p.kind = ParameterKind::kInteger;
  p.get = [m](const T& t) { return static_cast<double>(t.*m); };
  p.set = [m](T& t, double v) { t.*m = static_cast<V>(v); };
  return p;
}

/// The table of a member set M of T, as parameters of T (a sub-table lifted into its whole).
template <class T, class M>
std::vector<Parameter<T>> lift_parameters(const std::vector<Parameter<M>>& table, M T::*member) {
  std::vector<Parameter<T>> out;
  for (const Parameter<M>& p : table) {
    Parameter<T> q;
    static_cast<ParameterInfo&>(q) = p;
    q.get = [get = p.get, member](const T& t) { return get(t.*member); };
    q.set = [set = p.set, member](T& t, double v) { set(t.*member, v); };
    out.push_back(std::move(q));
  }
  return out;
}

/// The entry of key in table, or nullptr.
template <class T>
const Parameter<T>* find_parameter(const std::vector<Parameter<T>>& table, const std::string& key) {
  for (const Parameter<T>& p : table)
    if (key == p.key) return &p;
  return nullptr;
}

/// The message of a value outside its parameter's rule: "<key> = <value> <violation>".
std::string parameter_error(const ParameterInfo& parameter, double value, const std::string& violation);

/// Checks every parameter of value against its range, in table order.
/// @throws std::invalid_argument "<key> = <value> is outside <range> [<unit>]" for the first one
/// that is not valid.
template <class T>
void validate_parameters(const std::vector<Parameter<T>>& table, const T& value) {
  for (const Parameter<T>& p : table) {
    const double v = p.get(value);
    if (const std::optional<std::string> why = p.violation(v)) throw std::invalid_argument(parameter_error(p, v, *why));
  }
}

}  // namespace wrc
