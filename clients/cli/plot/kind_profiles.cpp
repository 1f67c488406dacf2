// SPDX-License-Identifier: Apache-2.0
// wrc plot profiles: the wheel and rail profiles of both wheels in the track cross-section, the
// rigid wheelset placed at lateral shift y (roll and height solved, both wheels touching), with the
// contact points and the other potential contact points marked.

#include <cmath>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/pose_ranges.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/rigid_wheelset.hpp"

namespace wrc::cli::plot {
namespace {

constexpr int kProfileSamples = 800;

int run_profiles(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  specs.push_back({"--y", true, "lateral shift of the wheelset [m] (> 0 towards the left rail)", "0",
      kLateralShiftRange});
  specs.push_back({"--yaw", true, "yaw angle of the wheelset [rad]", "0", kYawRange});
  for (const auto& spec : image_option_specs("profiles.png")) specs.push_back(spec);
  Options opt("plot profiles", "[--y Y] [--yaw PSI] [--out FILE] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nBoth wheels and rails in the track cross-section (for yaw != 0: the wheel's curve C, the points\n"
                 "whose normal lies in the cross-section), the rigid wheelset at lateral shift y with roll and\n"
                 "height solved, the contact points and the other potential contact points marked. Left wheel\n"
                 "left, right wheel right, each around its rail.\n";
    return 0;
  }
  const double y = opt.number("--y");
  const double yaw = opt.number("--yaw");
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const ImageRequest image = image_from_options(opt, "profiles.png");

  const RigidWheelsetSolver solver(geometry);
  const RigidContact contact = solver.solve(y, yaw);
  GnuplotJob job;
  std::string script = "set multiplot layout 1,2 title " +
                       plot::quoted("Profiles and contact points: " + geometry_title(spec) + "\n" +
                                    pose_title(contact.pose) + format(", z = %.2f mm", contact.pose.z * 1e3)) +
                       "\n";
  script += "set grid\nset size ratio -1\nset key below\n"
            "set xlabel 'lateral position in the track y [mm]'\nset ylabel 'height above the top of rail z [mm]'\n";
  for (const WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const int index = side == WheelSide::kLeft ? 0 : 1;
    const std::string name = side_name(side);
    const PlacedRail& rail = geometry.rail(side);
    const Profile& rail_profile = rail.profile();
    {
      auto out = job.open_data(name + "_rail.dat");
      for (int i = 0; i <= kProfileSamples; ++i) {
        const double u = rail_profile.lower() + (rail_profile.upper() - rail_profile.lower()) * i / kProfileSamples;
        double ry = 0, rz = 0;
        rail.profile_to_track(u, ry, rz);
        out << ry << " " << rz << "\n";
      }
    }
    const ContactLocus locus = geometry.locus(side, contact.pose);
    const Profile& wheel = geometry.wheel_profile();
    {
      auto out = job.open_data(name + "_wheel.dat");
      for (int i = 0; i <= kProfileSamples; ++i) {
        const LocusPoint p = locus.at(wheel.lower() + (wheel.upper() - wheel.lower()) * i / kProfileSamples);
        out << p.wheel.y() << " " << p.wheel.z() << "\n";
      }
    }
    {
      auto out = job.open_data(name + "_points.dat");
      for (const auto& p : contact.potential[index])
        out << p.wheel_point.y() << " " << p.wheel_point.z() << " " << p.is_minimum << "\n";
      out << "\n\n" << contact.contact[index].wheel_point.y() << " " << contact.contact[index].wheel_point.z() << "\n";
    }
    // Around the rail head: 45 mm to the field side and 35 mm towards the track centre, 25 mm high.
    const double gauge_y = rail.gauge_point_y();
    const double sign = side == WheelSide::kLeft ? 1 : -1;
    const double from = (gauge_y - sign * 35e-3) * 1e3, to = (gauge_y + sign * 75e-3) * 1e3;
    script += format("set xrange [%g:%g]\nset yrange [-35:25]\n", std::min(from, to), std::max(from, to));
    script += "set title " + plot::quoted(format("%s wheel: contact at s = %.2f mm, contact angle %.2f°", name.c_str(),
                                                 contact.contact[index].s * 1e3,
                                                 contact.contact[index].contact_angle * 180 / M_PI)) +
              "\n";
    const std::string points = plot::quoted(job.data_path(name + "_points.dat"));
    script += "plot " + plot::quoted(job.data_path(name + "_rail.dat")) +
              " using ($1*1e3):($2*1e3) with lines lw 2 lc rgb '#555555' title 'rail', " +
              plot::quoted(job.data_path(name + "_wheel.dat")) +
              " using ($1*1e3):($2*1e3) with lines lw 2 lc rgb '#1f77b4' title 'wheel', " + points +
              " index 0 using ($1*1e3):($3 == 1 ? $2*1e3 : 1/0) with points pt 6 ps 1.2 lc rgb '#2ca02c' "
              "title 'other local minima', " +
              points + " index 1 using ($1*1e3):($2*1e3) with points pt 7 ps 1.6 lc rgb '#d62728' title 'contact point'\n";
  }
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"profiles", "wheel and rail profiles of both wheels with the contact points marked", run_profiles, 6}};

}  // namespace
}  // namespace wrc::cli::plot
