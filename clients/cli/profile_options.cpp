// SPDX-License-Identifier: Apache-2.0
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"

namespace wrc::cli {

WheelsetGeometry geometry_from_options(const Options& options) {
  return make_geometry(geometry_spec_from_options(options));
}

std::vector<OptionSpec> pose_option_specs() {
  return {{"--y", true, "lateral shift of the wheelset [m] (> 0 towards the left rail)", "", kLateralShiftRange},
          {"--roll", true, "roll angle [rad] (> 0 raises the left wheel)", "0", NumberRange{-0.1, 0.1}},
          {"--yaw", true, "yaw angle [rad]", "0", kYawRange}};
}

OptionSpec side_option_spec() { return {"--wheel-side", true, "left or right", "left"}; }

WheelsetPose pose_from_options(const Options& options, double z) {
  WheelsetPose pose;
  pose.y = options.required_number("--y");
  pose.roll = options.number("--roll");
  pose.yaw = options.number("--yaw");
  pose.z = z;
  return pose;
}

WheelSide side_from_options(const Options& options) {
  return options.choice("--wheel-side", {"left", "right"}) == "left" ? WheelSide::kLeft : WheelSide::kRight;
}

}  // namespace wrc::cli
