// SPDX-License-Identifier: Apache-2.0
// wrc geometry: rigid-wheelset contact geometry (both wheels touching, roll and height solved)
// over a range of lateral shifts, as CSV or an aligned table.

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/numerics/inclusive_range.hpp"

namespace wrc::cli {
namespace {

int run_geometry(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--yaw", true, "yaw angle of the wheelset [rad], within +-0.06 (validated range)", "0", kYawRange});
  specs.push_back({"--y-from", true, "first lateral shift [m] (> 0 towards the left rail)", "", kLateralShiftRange});
  specs.push_back({"--y-to", true, "last lateral shift [m]", "", kLateralShiftRange});
  specs.push_back({"--y-step", true, "lateral step [m]", "", NumberRange{1e-7, 0.05}});
  specs.push_back({"--format", true, "csv or table", "table"});
  Options opt("geometry", "--y-from A --y-to B --y-step H [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nColumns: y,z,roll,r_left,r_right,delta_r,angle_left,angle_right,s_left,s_right [m, rad],\n"
                 "then u_left,u_right (rail profile coordinates) [m], x_left,x_right (longitudinal contact\n"
                 "positions) [m], n_left,n_right (potential common points), minima_left,minima_right.\n"
                 "z is the height of the wheelset centre above the top-of-rail plane.\n";
    return 0;
  }
  const double y_from = opt.required_number("--y-from");
  const double y_to = opt.required_number("--y-to");
  const double step = opt.required_number("--y-step");
  const double yaw = opt.number("--yaw");
  const bool csv = opt.choice("--format", {"csv", "table"}) == "csv";
  if (y_to < y_from) throw UsageError("--y-to " + std::to_string(y_to) + " is below --y-from " + std::to_string(y_from));
  const long count = inclusive_range_count(y_from, y_to, step);
  if (count > 2000000) throw UsageError("--y-step gives more than 2e6 rows");

  const WheelsetGeometry geometry = geometry_from_options(opt);
  const RigidWheelsetSolver solver(geometry);
  const char* header = "y,z,roll,r_left,r_right,delta_r,angle_left,angle_right,s_left,s_right,"
                       "u_left,u_right,x_left,x_right,n_left,n_right,minima_left,minima_right";
  if (csv) {
    std::printf("%s\n", header);
  } else {
    std::printf("%10s %10s %11s %10s %10s %11s %9s %9s %10s %10s %3s %3s\n", "y[mm]", "z[mm]", "roll[mrad]",
                "r_L[mm]", "r_R[mm]", "dr[mm]", "angL[deg]", "angR[deg]", "s_L[mm]", "s_R[mm]", "nL", "nR");
  }
  RigidContact previous;
  for (long i = 0; i < count; ++i) {
    const double y = y_from + static_cast<double>(i) * step;
    const RigidContact c = i == 0 ? solver.solve(y, yaw) : solver.solve(y, yaw, previous);
    previous = c;
    auto minima = [](const std::vector<ContactPoint>& v) {
      int n = 0;
      for (const auto& p : v) n += p.is_minimum;
      return n;
    };
    const ContactPoint& l = c.left();
    const ContactPoint& r = c.right();
    if (csv) {
      std::printf("%.9g,%.12g,%.9e,%.12g,%.12g,%.9e,%.9g,%.9g,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%zu,%zu,%d,%d\n", y,
                  c.pose.z, c.pose.roll, l.rolling_radius, r.rolling_radius, c.delta_r(), l.contact_angle,
                  r.contact_angle, l.s, r.s, l.s_rail, r.s_rail, l.wheel_point.x(), r.wheel_point.x(),
                  c.potential[0].size(), c.potential[1].size(), minima(c.potential[0]), minima(c.potential[1]));
    } else {
      const double deg = 180.0 / M_PI;
      std::printf("%10.4f %10.5f %11.5f %10.5f %10.5f %11.6f %9.4f %9.4f %10.4f %10.4f %3zu %3zu\n", y * 1e3,
                  c.pose.z * 1e3, c.pose.roll * 1e3, l.rolling_radius * 1e3, r.rolling_radius * 1e3,
                  c.delta_r() * 1e3, l.contact_angle * deg, r.contact_angle * deg, l.s * 1e3, r.s * 1e3,
                  c.potential[0].size(), c.potential[1].size());
    }
  }
  return 0;
}

const CommandRegistrar registrar{{"geometry", "rigid-wheelset contact geometry over a range of y", run_geometry}};

}  // namespace
}  // namespace wrc::cli
