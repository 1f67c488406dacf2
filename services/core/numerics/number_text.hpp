// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Numbers as text, the one way for every layer: a whole text read as one number (strtod's syntax,
/// leading white space allowed, nothing after the number), and a number written with a given
/// count of significant digits (printf's %g) or in its shortest exact form.

#include <optional>
#include <string>

namespace wrc {

/// The whole of text as one number (NaN and infinities included), or nothing when text is empty
/// or holds anything after the number.
std::optional<double> whole_number(const std::string& text);

/// The whole of text as one finite number, or nothing (also for a value beyond the range of a
/// double, too large or too small).
std::optional<double> finite_number(const std::string& text);

/// The message for a text that is not one finite number: "<what>: '<text>' is not a finite number".
std::string not_a_finite_number(const std::string& what, const std::string& text);

/// The whole of text as one finite number.
/// @throws std::invalid_argument not_a_finite_number(what, text) otherwise.
double parse_finite_number(const std::string& text, const std::string& what);

/// value with `digits` significant digits as printf's %g writes it ("0.06", "1e-06", "nan").
std::string number_text(double value, int digits = 9);

/// value with 17 significant digits, which reads back as the same double.
inline std::string exact_number_text(double value) { return number_text(value, 17); }

/// The shortest text that reads back as value, its exponent as people write it: "0.28", "30",
/// "8.2e10", "1e-6" (the parameter tables' values and the command line's defaults).
std::string shortest_number_text(double value);

}  // namespace wrc
