// SPDX-License-Identifier: Apache-2.0
#include "contactd/contactd_options.hpp"

#include <stdexcept>

#include "core/models/contact_model_factory.hpp"
#include "options/fit_options.hpp"
#include "options/geometry_options.hpp"
#include "options/options.hpp"

namespace wrc::contactd {

namespace {

// "onepoint, interp, multipoint, spline" from the registry.
std::string model_list() {
  std::string list;
  for (const std::string& n : contact_model_names()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

/// --model, then the profile and track options of the front end's geometry commands (one table),
/// then the spline fit's options (wrc fit's).
std::vector<OptionSpec> contactd_option_specs() {
  std::vector<OptionSpec> specs{{"--model", true, "contact model: " + model_list() + " (required)", ""}};
  for (OptionSpec& s : geometry_option_specs()) specs.push_back(std::move(s));
  for (OptionSpec& s : spline_model_fit_option_specs()) specs.push_back(std::move(s));
  return specs;
}

}  // namespace

ContactdOptions ContactdOptions::parse(const std::vector<std::string>& args) {
  ParseRules rules;
  rules.repeated = Repeated::kLastWins;  // as the options every service shares (bus/service/service_options.hpp)
  try {
    const Options parsed = Options::for_program("wrc-contactd", "[options]", contactd_option_specs(), args, rules);
    ContactdOptions options;
    if (parsed.has("--model")) {
      try {
        options.model = contact_model_entry(parsed.text("--model")).name;
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--model: ") + e.what());
      }
    }
    options.geometry = geometry_spec_from_options(parsed);
    if (options.model.empty()) throw std::invalid_argument("--model is required (" + model_list() + ")");
    const std::string fit_option = first_fit_option(parsed);
    if (!fit_option.empty() && !contact_model_entry(options.model).needs_data)
      throw std::invalid_argument(fit_option + ": a fit option, but the " + options.model +
                                  " model is not fitted (the spline model is)");
    options.fit = fit_options_from(parsed);
    return options;
  } catch (const UsageError& e) {
    throw std::invalid_argument(e.what());
  }
}

std::string ContactdOptions::help_text() { return Options::option_lines(contactd_option_specs()); }

}  // namespace wrc::contactd
