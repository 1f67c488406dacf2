// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Command-line options generated from a parameter table (core/numerics/parameter_table.hpp):
/// one option per entry (ParameterInfo::option_name()), its help "<description> [<unit>]" and
/// its --help default the table's, and the reader that checks each given value against the
/// table's rule, the same one the library's validate() and the message codecs apply.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/numerics/parameter_table.hpp"
#include "options/options.hpp"

namespace wrc {

/// The option of one table entry, with default the text of default_value [the entry's unit].
OptionSpec parameter_option_spec(const ParameterInfo& parameter, double default_value);

/// The value of parameter's option as given: parsed as the entry's kind and checked against its
/// range. @throws UsageError "<option>: <text> is outside <range> [<unit>]" (or why it is no value).
double parameter_option_value(const ParameterInfo& parameter, const std::string& text);

/// Option specs of every entry of table, defaults those of defaults (the set's own, T{}).
template <class Entry, class T>
std::vector<OptionSpec> parameter_option_specs(const std::vector<Entry>& table, const T& defaults) {
  std::vector<OptionSpec> specs;
  for (const Entry& p : table)
    if (p.has_option()) specs.push_back(parameter_option_spec(p, p.get(defaults)));
  return specs;
}

/// Sets every member of value whose option options hold; options not given keep value's, and
/// entries without an option of their own are the caller's.
template <class Entry, class T>
void apply_parameter_options(const std::vector<Entry>& table, const Options& options, T& value) {
  for (const Entry& p : table) {
    if (!p.has_option()) continue;
    const std::string name = p.option_name();
    if (options.has(name)) p.set(value, parameter_option_value(p, options.text(name)));
  }
}

}  // namespace wrc
