#include "cli/profile_options.hpp"

namespace wrc::cli {

WheelsetGeometry geometry_from_options(const Options& options) {
  return make_geometry(geometry_spec_from_options(options));
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
