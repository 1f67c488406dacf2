#include "options/geometry_options.hpp"

#include <stdexcept>
#include <string>

namespace wrc {

std::vector<OptionSpec> geometry_option_specs() {
  return {
      {"--wheel", true, "wheel profile: S1002, conic:<slope>, or a profile file", "S1002"},
      {"--rail", true, "rail profile: UIC60, UIC60-MB, circle:<radius [m]>, or a profile file", "UIC60"},
      {"--rail-cant", true, "inclination already contained in a rail profile file: 1:N, none or [rad] "
                            "(SIMPACK files saying 'canted': 1:40)", "from the file"},
      {"--gauge", true, "track gauge, measured --gauge-depth below the top of rail [m]", "1.435"},
      {"--gauge-depth", true, "depth below the top of rail where the gauge is measured [m]", "0.014"},
      {"--flange-back", true, "flange-back spacing [m]", "1.360"},
      {"--taping-line-offset", true, "distance of the taping line from the wheel's inner face [m]", "0.070"},
      {"--inclination", true, "rail inclination: 1:40, 1:20, none, or an angle [rad]", "1:40"},
      {"--r0", true, "nominal rolling radius [m]", "0.46"},
  };
}

GeometrySpec geometry_spec_from_options(const Options& options) {
  GeometrySpec spec;
  spec.wheel = options.text("--wheel", spec.wheel);
  spec.rail = options.text("--rail", spec.rail);
  TrackParameters& track = spec.track;
  if (options.has("--gauge")) track.gauge = options.number("--gauge", {0.5, 2.5});
  if (options.has("--gauge-depth")) track.gauge_depth = options.number("--gauge-depth", {0.0, 0.05});
  if (options.has("--flange-back")) track.flange_back_spacing = options.number("--flange-back", {0.4, 2.4});
  if (options.has("--taping-line-offset")) track.taping_line_offset = options.number("--taping-line-offset", {0.0, 0.2});
  if (options.has("--r0")) track.nominal_radius = options.number("--r0", {0.1, 1.5});
  if (options.has("--inclination")) {
    try {
      track.inclination = parse_inclination(options.text("--inclination"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--inclination: ") + e.what());
    }
  }
  track.validate();
  if (options.has("--rail-cant")) {
    try {
      spec.rail_cant = parse_inclination(options.text("--rail-cant"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--rail-cant: ") + e.what());
    }
  }
  return spec;
}

}  // namespace wrc
