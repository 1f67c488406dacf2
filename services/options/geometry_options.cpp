// SPDX-License-Identifier: Apache-2.0
#include "options/geometry_options.hpp"

#include <stdexcept>
#include <string>

#include "core/geometry/track_table.hpp"
#include "core/profile/builtin_profiles.hpp"
#include "options/parameter_options.hpp"

namespace wrc {

namespace {

// The profiles a side's option takes: its built-in names, its one-parameter form, or a file
// ("S1002, conic:<slope>, or a profile file").
std::string profile_choices(ProfileSide side, const std::string& parametric) {
  std::string text;
  for (const BuiltinProfile& p : kBuiltinProfiles)
    if (p.side == side) text += std::string(p.name) + ", ";
  return text + parametric + ", or a profile file";
}

}  // namespace

std::vector<OptionSpec> geometry_option_specs() {
  std::vector<OptionSpec> specs{
      {"--wheel", true, "wheel profile: " + profile_choices(ProfileSide::kWheel, std::string(kConicPrefix) + "<slope>"),
       GeometrySpec{}.wheel},
      {"--rail", true,
       "rail profile: " + profile_choices(ProfileSide::kRail, std::string(kCirclePrefix) + "<radius [m]>"),
       GeometrySpec{}.rail},
      {"--rail-cant", true, "inclination already contained in a rail profile file: 1:N, none or [rad] "
                            "(SIMPACK files saying 'canted': 1:40)", "from the file"},
  };
  for (auto& spec : parameter_option_specs(track_parameter_table(), TrackParameters{})) specs.push_back(spec);
  return specs;
}

GeometrySpec geometry_spec_from_options(const Options& options) {
  GeometrySpec spec;
  spec.wheel = options.text("--wheel", spec.wheel);
  spec.rail = options.text("--rail", spec.rail);
  apply_parameter_options(track_parameter_table(), options, spec.track);
  spec.track.validate();
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
