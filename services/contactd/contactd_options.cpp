#include "contactd/contactd_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/models/contact_model_factory.hpp"

namespace wrc::contactd {

namespace {

// "onepoint, interp, multipoint, spline" from the registry.
std::string model_list() {
  std::string list;
  for (const std::string& n : contact_model_names()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

double parse_number(const std::string& option, const std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < lo || value > hi) {
    throw std::invalid_argument(option + ": '" + text + "' is not a number in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]");
  }
  return value;
}

}  // namespace

ContactdOptions ContactdOptions::parse(const std::vector<std::string>& args) {
  ContactdOptions options;
  TrackParameters& track = options.geometry.track;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string option = args[i];
    std::string value;
    if (auto eq = option.find('='); option.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = option.substr(eq + 1);
      option = option.substr(0, eq);
    } else {
      if (option.rfind("--", 0) != 0) throw std::invalid_argument("unexpected argument '" + option + "'");
      if (i + 1 >= args.size()) throw std::invalid_argument("option " + option + " needs a value");
      value = args[++i];
    }
    if (option == "--model") {
      try {
        options.model = contact_model_entry(value).name;
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--model: ") + e.what());
      }
    } else if (option == "--wheel") {
      options.geometry.wheel = value;
    } else if (option == "--rail") {
      options.geometry.rail = value;
    } else if (option == "--rail-cant") {
      try {
        options.geometry.rail_cant = parse_inclination(value);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--rail-cant: ") + e.what());
      }
    } else if (option == "--gauge") {
      track.gauge = parse_number(option, value, 0.5, 2.5);
    } else if (option == "--gauge-depth") {
      track.gauge_depth = parse_number(option, value, 0.0, 0.05);
    } else if (option == "--flange-back") {
      track.flange_back_spacing = parse_number(option, value, 0.4, 2.4);
    } else if (option == "--taping-line-offset") {
      track.taping_line_offset = parse_number(option, value, 0.0, 0.2);
    } else if (option == "--r0") {
      track.nominal_radius = parse_number(option, value, 0.1, 1.5);
    } else if (option == "--inclination") {
      try {
        track.inclination = parse_inclination(value);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--inclination: ") + e.what());
      }
    } else {
      throw std::invalid_argument("unknown option '" + option + "' (see --help)");
    }
  }
  if (options.model.empty()) throw std::invalid_argument("--model is required (" + model_list() + ")");
  track.validate();
  return options;
}

std::string ContactdOptions::help_text() {
  return "  --model M               contact model: " + model_list() + " (required)\n" +
         std::string("  --wheel W               wheel profile: S1002, conic:<slope>, or a profile file (default S1002)\n"
         "  --rail R                rail profile: UIC60, UIC60-MB, circle:<radius [m]>, or a file (default UIC60)\n"
         "  --rail-cant C           inclination already in the rail profile: 1:N, none or [rad] (default: the file's)\n"
         "  --gauge G               track gauge [m], measured --gauge-depth below the top of rail (default 1.435)\n"
         "  --gauge-depth D         depth of the gauge measurement [m] (default 0.014)\n"
         "  --flange-back F         flange-back spacing [m] (default 1.360)\n"
         "  --taping-line-offset T  taping line from the wheel's inner face [m] (default 0.070)\n"
         "  --inclination I         rail inclination: 1:40, 1:20, none, or an angle [rad] (default 1:40)\n"
         "  --r0 R0                 nominal rolling radius [m] (default 0.46)\n");
}

}  // namespace wrc::contactd
