#include "geometryd/geometryd_options.hpp"

#include <cstdlib>
#include <stdexcept>

namespace wrc::geometryd {

namespace {
/// The variable's value; empty when unset.
std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value == nullptr ? std::string() : std::string(value);
}
}  // namespace

GeometrydOptions GeometrydOptions::parse(const std::vector<std::string>& args) {
  GeometrydOptions options;
  bool cache_dir_given = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string option = args[i];
    std::string value;
    if (auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = option.substr(eq + 1);
      option = option.substr(0, eq);
    } else if (option == "--cache-dir") {
      if (i + 1 >= args.size()) throw std::invalid_argument("option --cache-dir needs a value");
      value = args[++i];
    }
    if (option != "--cache-dir") {
      throw std::invalid_argument(std::string(option.rfind("--", 0) == 0 ? "unknown option '" : "unexpected argument '") +
                                  option + "' (see --help)");
    }
    if (value.empty()) throw std::invalid_argument("--cache-dir: the directory name is empty");
    options.cache_dir = value;
    cache_dir_given = true;
  }
  if (!cache_dir_given) options.cache_dir = default_cache_dir();
  return options;
}

std::string GeometrydOptions::help_text() {
  return "  --cache-dir DIR         model files <DIR>/<model_key>.splinemodel, created 0700 if missing\n"
         "                          (default $WRC_CACHE_DIR, else $XDG_CACHE_HOME/wrc/models,\n"
         "                          else $HOME/.cache/wrc/models)\n";
}

std::string default_cache_dir() {
  if (std::string dir = environment("WRC_CACHE_DIR"); !dir.empty()) return dir;
  if (std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/wrc/models";
  if (std::string home = environment("HOME"); !home.empty()) return home + "/.cache/wrc/models";
  throw std::runtime_error("no cache directory: none of WRC_CACHE_DIR, XDG_CACHE_HOME, HOME is set (use --cache-dir)");
}

}  // namespace wrc::geometryd
