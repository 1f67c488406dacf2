// SPDX-License-Identifier: Apache-2.0
// wrc plot distance: the paper's figures 1-3, top: the vertical distance between wheel and rail
// along the curve C relative to the common point, over the lateral position of the wheel point,
// in a 0-1 mm and a 0-20 um view, with the potential common points marked.

#include <cmath>
#include <iostream>

#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/contact_area.hpp"

namespace wrc::cli::plot {
namespace {

int run_distance(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  for (auto& spec : pose_option_specs()) specs.push_back(spec);
  specs.push_back(side_option_spec());
  specs.push_back({"--samples", true, "points along C [-]", "4000", NumberRange{10, 1000000}});
  for (const auto& spec : image_option_specs("distance.png")) specs.push_back(spec);
  Options opt("plot distance", "--y Y [--roll PHI] [--yaw PSI] [--wheel-side left|right] [--out FILE] [options]",
              specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe paper's figures 1-3, top: the vertical distance between wheel and rail along the curve C,\n"
                 "minus the common point's, over the track lateral position of the wheel point, in two views\n"
                 "(0-1 mm and 0-20 um); the potential common points (local extrema along C) are marked.\n";
    return 0;
  }
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const WheelsetPose pose = pose_from_options(opt, geometry.track().nominal_radius);
  const WheelSide side = side_from_options(opt);
  const int samples = opt.integer("--samples");
  const ImageRequest image = image_from_options(opt, "distance.png");

  const auto points = geometry.potential_points(side, pose);
  const auto common = select_common_point(points);
  if (!common)
    throw std::runtime_error(format("the %s wheel has no common point with its rail at y = %g m", side_name(side), pose.y));
  const ContactLocus locus = geometry.locus(side, pose);

  GnuplotJob job;
  {
    auto out = job.open_data("locus.dat");
    out << "# lateral_position[m] distance_above_common_point[m] s[m]\n";
    for (const auto& sample : sample_locus_distance(locus, common->distance, samples)) {
      if (std::isnan(sample.distance)) out << "\n";  // a gap where C is not over the rail
      else out << sample.y << " " << sample.distance << " " << sample.s << "\n";
    }
  }
  {
    auto out = job.open_data("points.dat");
    out << "# lateral_position[m] distance_above_common_point[m] local_min common\n";
    for (const auto& p : points)
      out << p.wheel_point.y() << " " << p.distance - common->distance << " " << p.is_minimum << " "
          << (std::fabs(p.s - common->s) < 1e-12) << "\n";
  }
  const std::string title = format("Distance along C, %s wheel: ", side_name(side)) + geometry_title(spec) + "\n" +
                            pose_title(pose) + format(", common point s = %.2f mm", common->s * 1e3);
  std::string script;
  script += "set multiplot layout 2,1 title " + quoted(title) + "\n";
  script += "set grid\nset key top left\nset xlabel 'lateral position of the wheel point y [mm]'\n";
  const std::string locus_file = quoted(job.data_path("locus.dat"));
  const std::string points_file = quoted(job.data_path("points.dat"));
  for (const auto& view : {std::pair<double, std::string>{1e3, "mm"}, {1e6, "µm"}}) {
    const double scale = view.first;
    const double top = scale == 1e3 ? 1.0 : 20.0;
    script += format("set yrange [0:%g]\n", top);
    script += "set ylabel 'distance above the common point [" + view.second + "]'\n";
    script += format("plot %s using ($1*1e3):($2*%g) with lines lw 1.5 title 'distance along C', ", locus_file.c_str(),
                     scale);
    script += format("%s using ($1*1e3):($3 == 1 ? $2*%g : 1/0) with points pt 7 ps 1.2 title 'local minima', ",
                     points_file.c_str(), scale);
    script += format("%s using ($1*1e3):($4 == 1 ? $2*%g : 1/0) with points pt 6 ps 2.5 lw 2 title 'common point'\n",
                     points_file.c_str(), scale);
  }
  script += "unset multiplot\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"distance", "distance between wheel and rail along C for a pose (figures 1-3, top)", run_distance, 1}};

}  // namespace
}  // namespace wrc::cli::plot
