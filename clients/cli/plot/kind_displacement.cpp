// SPDX-License-Identifier: Apache-2.0
// wrc plot displacement: the paper's figure 4 for one wheel: over the plane of lateral shift y and
// roll angle, the common point (its wheel profile coordinate s) and the vertical displacement of
// the wheel (the vertical distance of the common point at the nominal height: how far the wheelset
// centre must move down from z = r0 for the wheel to touch), as colour maps.

#include <cmath>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/wheelset_geometry.hpp"

namespace wrc::cli::plot {
namespace {

int run_displacement(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--y-max", true, "the map covers y in [-Y, Y] [m]", "0.01", NumberRange{1e-5, 0.05}});
  specs.push_back({"--roll-max", true, "the map covers roll in [-R, R] [rad]", "0.02", NumberRange{1e-5, 0.1}});
  specs.push_back({"--yaw", true, "yaw angle [rad]", "0", kYawRange});
  specs.push_back(side_option_spec());
  specs.push_back({"--grid", true, "nodes per direction [-]", "81", NumberRange{2, 1001}});
  for (const auto& spec : image_option_specs("displacement.png")) specs.push_back(spec);
  Options opt("plot displacement", "[--y-max Y] [--roll-max R] [--yaw PSI] [--wheel-side left|right] [--grid N] "
              "[--out FILE] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe paper's figure 4 for one wheel, over lateral shift y and roll angle: the common point (wheel\n"
                 "profile coordinate s) and the vertical displacement (the common point's vertical distance with\n"
                 "the wheelset centre at z = r0; the wheel touches after moving down by it), as colour maps.\n"
                 "Jumps of the common point show as sharp colour edges.\n";
    return 0;
  }
  const double y_max = opt.number("--y-max");
  const double roll_max = opt.number("--roll-max");
  const double yaw = opt.number("--yaw");
  const WheelSide side = side_from_options(opt);
  const int nodes = opt.integer("--grid");
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const ImageRequest image = image_from_options(opt, "displacement.png");

  GnuplotJob job;
  {
    auto out = job.open_data("map.dat");
    out << "# y[m] roll[rad] s[m] vertical_displacement[m] (NaN: off the rail)\n";
    for (int j = 0; j < nodes; ++j) {
      const double roll = -roll_max + 2 * roll_max * j / (nodes - 1);
      for (int i = 0; i < nodes; ++i) {
        WheelsetPose pose;
        pose.y = -y_max + 2 * y_max * i / (nodes - 1);
        pose.roll = roll;
        pose.yaw = yaw;
        pose.z = geometry.track().nominal_radius;
        const auto common = geometry.common_point(side, pose);
        out << pose.y << " " << roll << " ";
        if (common) out << common->s << " " << common->distance << "\n";
        else out << "NaN NaN\n";
      }
      out << "\n";  // gnuplot's grid format: a blank line after each row
    }
  }
  const std::string data = plot::quoted(job.data_path("map.dat"));
  std::string script = "set multiplot layout 1,2 title " +
                       plot::quoted(format("Common point and vertical displacement, %s wheel: ", side_name(side)) +
                                    geometry_title(spec) + format("\nyaw = %.2f mrad, wheelset centre at z = r0 = %.1f mm",
                                                                  yaw * 1e3, geometry.track().nominal_radius * 1e3)) +
                       "\n";
  script += "set view map\nset pm3d map corners2color c1\nset size square\nunset key\n"
            "set xlabel 'lateral shift y [mm]'\nset ylabel 'roll angle [mrad]'\nset palette rgb 33,13,10\n";
  script += "set title 'common point: wheel profile coordinate s [mm]'\nset cblabel 's [mm]'\n";
  script += "splot " + data + " using ($1*1e3):($2*1e3):($3*1e3) with pm3d\n";
  script += "set title 'vertical displacement [mm]'\nset cblabel 'vertical displacement [mm]'\n";
  script += "splot " + data + " using ($1*1e3):($2*1e3):($4*1e3) with pm3d\n";
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"displacement", "common point and vertical displacement over (y, roll) as maps (figure 4)", run_displacement, 7}};

}  // namespace
}  // namespace wrc::cli::plot
