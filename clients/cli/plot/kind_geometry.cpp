// SPDX-License-Identifier: Apache-2.0
// wrc plot geometry: what every contact-geometry tool shows, against the lateral shift of the
// rigid wheelset: rolling-radius difference, contact angles, rolling radii and the contact points
// on wheel and rail, drawn as points so that jumps of the contact point stay visible.

#include <cmath>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/numerics/inclusive_range.hpp"

namespace wrc::cli::plot {
namespace {

int run_geometry(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--yaw", true, "yaw angle of the wheelset [rad]", "0", kYawRange});
  specs.push_back({"--y-from", true, "first lateral shift [m] (> 0 towards the left rail)", "-0.01",
      kLateralShiftRange});
  specs.push_back({"--y-to", true, "last lateral shift [m]", "0.01", kLateralShiftRange});
  specs.push_back({"--y-step", true, "lateral step [m]", "5e-5", NumberRange{1e-7, 0.05}});
  for (const auto& spec : image_option_specs("geometry.png")) specs.push_back(spec);
  Options opt("plot geometry", "[--y-from A] [--y-to B] [--y-step H] [--yaw PSI] [--out FILE] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe rigid wheelset (both wheels touching, roll and height solved) against its lateral shift y:\n"
                 "rolling-radius difference r_left - r_right, contact angles, rolling radii, and the contact points\n"
                 "on the wheel profile (s) and on the rail profile (u). Points, not lines: jumps stay visible.\n";
    return 0;
  }
  const double y_from = opt.number("--y-from");
  const double y_to = opt.number("--y-to");
  const double step = opt.number("--y-step");
  const double yaw = opt.number("--yaw");
  if (!(y_to > y_from)) throw UsageError(format("--y-to %g is not above --y-from %g", y_to, y_from));
  const long count = inclusive_range_count(y_from, y_to, step);
  if (count > 200000) throw UsageError(format("--y-step %g gives more than 200000 shifts", step));
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const ImageRequest image = image_from_options(opt, "geometry.png");

  const RigidWheelsetSolver solver(geometry);
  GnuplotJob job;
  {
    auto out = job.open_data("geometry.dat");
    out << "# y delta_r angle_left angle_right r_left r_right s_left s_right u_left u_right [m, rad]\n";
    RigidContact previous;
    for (long i = 0; i < count; ++i) {
      const double y = y_from + static_cast<double>(i) * step;
      const RigidContact c = i == 0 ? solver.solve(y, yaw) : solver.solve(y, yaw, previous);
      previous = c;
      const ContactPoint& l = c.left();
      const ContactPoint& r = c.right();
      out << y << " " << c.delta_r() << " " << l.contact_angle << " " << r.contact_angle << " " << l.rolling_radius
          << " " << r.rolling_radius << " " << l.s << " " << r.s << " " << l.s_rail << " " << r.s_rail << "\n";
    }
  }
  const std::string data = quoted(job.data_path("geometry.dat"));
  const std::string title = "Rigid-wheelset contact geometry: " + geometry_title(spec) +
                            format("\nlateral shift y from %.1f to %.1f mm, yaw = %.2f mrad", y_from * 1e3, y_to * 1e3,
                                   yaw * 1e3);
  const std::string dots = " with points pt 7 ps 0.35";
  std::string script = "set multiplot layout 2,2 title " + quoted(title) + "\n";
  script += "set grid\nset key top left\nset xlabel 'lateral shift of the wheelset y [mm]'\n";
  script += "set ylabel 'rolling-radius difference r_left - r_right [mm]'\n";
  script += "plot " + data + " using ($1*1e3):($2*1e3)" + dots + " title 'Δr'\n";
  script += "set ylabel 'contact angle [°]'\n";
  script += "plot " + data + " using ($1*1e3):($3*180/pi)" + dots + " title 'left', " + data +
            " using ($1*1e3):($4*180/pi)" + dots + " title 'right'\n";
  script += "set ylabel 'rolling radius [mm]'\n";
  script += "plot " + data + " using ($1*1e3):($5*1e3)" + dots + " title 'left', " + data + " using ($1*1e3):($6*1e3)" +
            dots + " title 'right'\n";
  script += "set ylabel 'contact point: wheel s, rail u [mm]'\n";
  script += "plot " + data + " using ($1*1e3):($7*1e3)" + dots + " title 'wheel, left', " + data +
            " using ($1*1e3):($8*1e3)" + dots + " title 'wheel, right', " + data + " using ($1*1e3):($9*1e3)" + dots +
            " title 'rail, left', " + data + " using ($1*1e3):($10*1e3)" + dots + " title 'rail, right'\n";
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"geometry", "rolling-radius difference, contact angles, radii and contact points against lateral shift",
     run_geometry, 3}};

}  // namespace
}  // namespace wrc::cli::plot
