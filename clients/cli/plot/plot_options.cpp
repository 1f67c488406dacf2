// SPDX-License-Identifier: Apache-2.0
#include "cli/plot/plot_options.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>

namespace wrc::cli::plot {

std::vector<OptionSpec> image_option_specs(const std::string& default_out) {
  return {{"--out", true, "output picture, .png or .svg", default_out},
          {"--width", true, "picture width [px]", "1200", NumberRange{1, 100000}},
          {"--height", true, "picture height [px]", "900", NumberRange{1, 100000}}};
}

ImageRequest image_from_options(const Options& options, const std::string& default_out) {
  return image_request(options.text("--out", default_out), options.integer("--width"),
                       options.integer("--height"));
}

std::string format(const char* pattern, ...) {
  va_list args;
  va_start(args, pattern);
  char buffer[1024];
  std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  return buffer;
}

std::string geometry_title(const GeometrySpec& spec) {
  const auto name = [](const std::string& profile) { return std::filesystem::path(profile).filename().string(); };
  const double inclination = spec.track.inclination;
  std::string incline = inclination == 0 ? "none" : format("1:%.0f", 1.0 / std::tan(inclination));
  return name(spec.wheel) + " on " + name(spec.rail) + format(", gauge %.0f mm, inclination ", spec.track.gauge * 1e3) +
         incline;
}

std::string pose_title(const WheelsetPose& pose) {
  return format("y = %.2f mm, roll = %.2f mrad, yaw = %.2f mrad", pose.y * 1e3, pose.roll * 1e3, pose.yaw * 1e3);
}

int report_written(const ImageRequest& image) {
  std::printf("wrote %s (%d x %d px)\n", image.path.c_str(), image.width, image.height);
  return 0;
}

}  // namespace wrc::cli::plot
