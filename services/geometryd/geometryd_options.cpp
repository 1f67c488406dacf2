// SPDX-License-Identifier: Apache-2.0
#include "geometryd/geometryd_options.hpp"

#include <cstdlib>
#include <stdexcept>

#include "options/options.hpp"

namespace wrc::geometryd {

namespace {
/// The variable's value; empty when unset.
std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::string() : std::string(value);
}

std::vector<OptionSpec> geometryd_option_specs() {
  return {{"--cache-dir", true,
           "model files <DIR>/<model_key>.splinemodel, created 0700 if missing",
           "$WRC_CACHE_DIR, else $XDG_CACHE_HOME/wrc/models, else $HOME/.cache/wrc/models"}};
}
}  // namespace

GeometrydOptions GeometrydOptions::parse(const std::vector<std::string>& args) {
  ParseRules rules;
  rules.repeated = Repeated::kLastWins;  // as the options every service shares (bus/service/service_options.hpp)
  const Options parsed = [&] {
    try {
      return Options::for_program("wrc-geometryd", "[options]", geometryd_option_specs(), args, rules);
    } catch (const UsageError& e) {
      throw std::invalid_argument(e.what());
    }
  }();
  GeometrydOptions options;
  if (!parsed.has("--cache-dir")) {
    options.cache_dir = default_cache_dir();
    return options;
  }
  options.cache_dir = parsed.text("--cache-dir");
  if (options.cache_dir.empty()) throw std::invalid_argument("--cache-dir: the directory name is empty");
  return options;
}

std::string GeometrydOptions::help_text() { return Options::option_lines(geometryd_option_specs()); }

std::string default_cache_dir() {
  if (std::string dir = environment("WRC_CACHE_DIR"); !dir.empty()) return dir;
  if (std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/wrc/models";
  if (std::string home = environment("HOME"); !home.empty()) return home + "/.cache/wrc/models";
  throw std::runtime_error("no cache directory: none of WRC_CACHE_DIR, XDG_CACHE_HOME, HOME is set (use --cache-dir)");
}

}  // namespace wrc::geometryd
