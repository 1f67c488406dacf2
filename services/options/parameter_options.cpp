// SPDX-License-Identifier: Apache-2.0
#include "options/parameter_options.hpp"

namespace wrc {

OptionSpec parameter_option_spec(const ParameterInfo& parameter, double default_value) {
  std::string help = parameter.description;
  if (std::string(parameter.unit) != "-") help += std::string(" [") + parameter.unit + "]";
  if (parameter.kind == ParameterKind::kBoolean) help += " (true or false)";
  return {parameter.option_name(), true, help,
          parameter.shown_default ? parameter.shown_default : parameter.value_text(default_value)};
}

double parameter_option_value(const ParameterInfo& parameter, const std::string& text) {
  const std::string name = parameter.option_name();
  double value = 0.0;
  try {
    value = parameter.parse(text, name);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (const std::optional<std::string> why = parameter.violation(value)) throw UsageError(name + ": " + text + " " + *why);
  return value;
}

}  // namespace wrc
