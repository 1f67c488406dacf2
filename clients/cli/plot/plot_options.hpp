// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What every `wrc plot` kind shares: the output options (--out, --width, --height) and the words
/// of the titles (profiles, track, pose).

#include <string>
#include <vector>

#include "cli/options.hpp"
#include "cli/plot/gnuplot_job.hpp"
#include "core/geometry/geometry_spec.hpp"
#include "core/geometry/wheelset_pose.hpp"

namespace wrc::cli::plot {

/// --out (default default_out), --width and --height [px].
std::vector<OptionSpec> image_option_specs(const std::string& default_out);

/// The image request of --out, --width, --height.
ImageRequest image_from_options(const Options& options, const std::string& default_out);

/// "S1002 on UIC60, gauge 1435 mm, inclination 1:40": profile names (file names without their
/// folders) and track.
std::string geometry_title(const GeometrySpec& spec);

/// "y = 3.00 mm, roll = 0.00 mrad, yaw = 0.00 mrad".
std::string pose_title(const WheelsetPose& pose);

/// printf-style formatting into a std::string.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// Prints where the picture went (one line on stdout) and returns 0.
int report_written(const ImageRequest& image);

}  // namespace wrc::cli::plot
