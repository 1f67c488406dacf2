// SPDX-License-Identifier: Apache-2.0
// wrc points: every potential common point of one wheel for one wheelset pose.

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc::cli {
namespace {

int run_points(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  for (auto& spec : pose_option_specs()) specs.push_back(spec);
  specs.push_back({"--z", true, "height of the wheelset centre above the top of rail [m]; distances are shifted by it",
                   "r0", NumberRange{0.0, 2.0}});
  specs.push_back(side_option_spec());
  specs.push_back({"--format", true, "csv or table", "table"});
  Options opt("points", "--y Y [--roll PHI] [--yaw PSI] [--wheel-side left|right] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nOne row per potential common point (zeros of d(distance)/ds along the curve C), flange first:\n"
                 "s (wheel profile coordinate), u (rail profile coordinate), x,y,z of the wheel point, distance\n"
                 "(vertical, wheel minus rail, at the given z), contact angle, rolling radius, wheel and rail\n"
                 "lateral curvatures, local_min (1 for a local minimum of the distance), common (1 for the\n"
                 "common point: the smallest minimum, on a tie the one farthest from the flange). SI units.\n";
    return 0;
  }
  const WheelsetGeometry geometry = geometry_from_options(opt);
  const WheelsetPose pose =
      pose_from_options(opt, opt.has("--z") ? opt.number("--z") : geometry.track().nominal_radius);
  const WheelSide side = side_from_options(opt);
  const bool csv = opt.choice("--format", {"csv", "table"}) == "csv";
  const auto points = geometry.potential_points(side, pose);
  const auto common = select_common_point(points);
  if (csv) {
    std::printf("s,u,x,y,z,distance,angle,rolling_radius,wheel_curvature,rail_curvature,local_min,common\n");
  } else {
    std::printf("%s wheel, %zu potential common points\n", side_name(side), points.size());
    std::printf("%10s %10s %9s %10s %10s %12s %9s %10s %10s %10s %4s %4s\n", "s[mm]", "u[mm]", "x[mm]", "y[mm]",
                "z[mm]", "dist[um]", "ang[deg]", "r[mm]", "kw[1/m]", "kr[1/m]", "min", "cp");
  }
  for (const auto& p : points) {
    const bool is_common = common && std::fabs(common->s - p.s) < 1e-12;
    if (csv) {
      std::printf("%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.12e,%.9e,%.9e,%d,%d\n", p.s, p.s_rail,
                  p.wheel_point.x(), p.wheel_point.y(), p.wheel_point.z(), p.distance, p.contact_angle,
                  p.rolling_radius, p.wheel_curvature_lateral, p.rail_curvature_lateral, p.is_minimum, is_common);
    } else {
      std::printf("%10.4f %10.4f %9.4f %10.4f %10.4f %12.3f %9.4f %10.4f %10.3f %10.3f %4d %4d\n", p.s * 1e3,
                  p.s_rail * 1e3, p.wheel_point.x() * 1e3, p.wheel_point.y() * 1e3, p.wheel_point.z() * 1e3,
                  p.distance * 1e6, p.contact_angle * 180 / M_PI, p.rolling_radius * 1e3, p.wheel_curvature_lateral,
                  p.rail_curvature_lateral, p.is_minimum, is_common);
    }
  }
  return 0;
}

const CommandRegistrar registrar{{"points", "every potential common point of one wheel", run_points}};

}  // namespace
}  // namespace wrc::cli
