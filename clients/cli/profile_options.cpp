#include "cli/profile_options.hpp"

#include <stdexcept>

#include "core/profile/profile_factory.hpp"

namespace wrc::cli {

std::vector<OptionSpec> profile_option_specs() {
  return {
      {"--wheel", true, "wheel profile: S1002, conic:<slope>, or a profile file", "S1002"},
      {"--rail", true, "rail profile: UIC60, UIC60-MB, circle:<radius [m]>, or a profile file", "UIC60"},
      {"--rail-cant", true, "inclination already contained in a rail profile file: 1:N, none or [rad] "
                            "(SIMPACK files saying 'canted': 1:40)", "from the file"},
      {"--gauge", true, "track gauge, measured --gauge-depth below the top of rail [m]", "1.435"},
      {"--gauge-depth", true, "depth below the top of rail where the gauge is measured [m]", "0.014"},
      {"--flange-back", true, "flange-back spacing [m]", "1.360"},
      {"--inclination", true, "rail inclination: 1:40, 1:20, none, or an angle [rad]", "1:40"},
      {"--r0", true, "nominal rolling radius [m]", "0.46"},
  };
}

WheelsetGeometry geometry_from_options(const Options& options) {
  TrackParameters track;
  track.gauge = options.number("--gauge", track.gauge, 0.5, 2.5);
  track.gauge_depth = options.number("--gauge-depth", track.gauge_depth, 0.0, 0.05);
  track.flange_back_spacing = options.number("--flange-back", track.flange_back_spacing, 0.4, 2.4);
  track.nominal_radius = options.number("--r0", track.nominal_radius, 0.1, 1.5);
  if (options.has("--inclination")) {
    try {
      track.inclination = parse_inclination(options.text("--inclination"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--inclination: ") + e.what());
    }
  }
  track.validate();
  auto wheel = make_profile(options.text("--wheel", "S1002"), ProfileSide::kWheel);
  ProfileFileOptions rail_options;
  if (options.has("--rail-cant")) {
    try {
      rail_options.built_in_cant = parse_inclination(options.text("--rail-cant"));
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--rail-cant: ") + e.what());
    }
  }
  auto rail = make_profile(options.text("--rail", "UIC60"), ProfileSide::kRail, rail_options);
  return WheelsetGeometry(wheel, rail, track);
}

WheelsetPose pose_from_options(const Options& options, double z) {
  WheelsetPose pose;
  pose.y = options.required_number("--y", -0.05, 0.05);
  pose.roll = options.number("--roll", 0.0, -0.1, 0.1);
  pose.yaw = options.number("--yaw", 0.0, -kMaxValidatedYaw, kMaxValidatedYaw);
  pose.z = z;
  return pose;
}

WheelSide side_from_options(const Options& options) {
  return options.choice("--wheel-side", {"left", "right"}, "left") == "left" ? WheelSide::kLeft : WheelSide::kRight;
}

}  // namespace wrc::cli
