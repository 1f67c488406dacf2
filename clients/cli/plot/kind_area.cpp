// SPDX-License-Identifier: Apache-2.0
// wrc plot area: the paper's figures 1-3, bottom: the contact area of one wheel in the common
// tangent plane E, as the outlines of the region distance < eps0 for eps0 = 25, 50, ... um, with the
// Hertz ellipse at the common point for a given normal force, and with --spline the ellipse of the
// spline model (fitted in-process, the options of wrc fit) at its fitted contact point.

#include <cmath>
#include <iostream>

#include "options/fit_options.hpp"
#include "cli/plot/contour_lines.hpp"
#include "cli/plot/plot_kind.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/profile_options.hpp"
#include "core/contact/hertz.hpp"
#include "core/geometry/contact_area.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/contact_model_options.hpp"
#include "core/model_interface/patch_builder.hpp"
#include "core/spline/spline_geometry_fit.hpp"

namespace wrc::cli::plot {
namespace {

// Writes the ellipse with semi-axes a (along xi) and b (along eta) [m] centred at (xi, eta) [m] as
// eta xi rows.
void write_ellipse(std::ofstream& out, double a, double b, double xi, double eta) {
  for (int i = 0; i <= 360; ++i) {
    const double t = 2 * M_PI * i / 360;
    out << eta + b * std::sin(t) << " " << xi + a * std::cos(t) << "\n";
  }
}

std::vector<OptionSpec> area_option_specs() {
  auto specs = profile_option_specs();
  for (auto& spec : pose_option_specs()) specs.push_back(spec);
  specs.push_back(side_option_spec());
  specs.push_back({"--eps0", true, "largest level [m] (levels every 25 um up to it)", "1.5e-4",
      NumberRange{25e-6, 0.01}});
  specs.push_back({"--normal-force", true, "normal force of the Hertz ellipse [N] (0: no ellipse)", "75000",
      NumberRange{0.0, 1e7}});
  specs.push_back({"--grid", true, "grid nodes per direction [-]", "161", NumberRange{3, 2001}});
  specs.push_back({"--half-width", true, "half width of the square grid in E [m]", "0.02", NumberRange{1e-4, 0.1}});
  specs.push_back({"--spline", false, "also the spline model's ellipse (fits the model first, a few seconds)", ""});
  for (const auto& spec : fit_option_specs()) specs.push_back(spec);
  for (const auto& spec : image_option_specs("area.png")) specs.push_back(spec);
  return specs;
}

// Appends one plot clause to the gnuplot plot command.
void add_plot(std::string& plots, const std::string& clause) { plots += (plots.empty() ? "" : ", ") + clause; }

// The outlines distance = 25, 50, ... um up to eps0 [m], one data file per level.
void add_level_lines(GnuplotJob& job, const ContactArea& area, double eps0, std::string& plots) {
  const double step = 25e-6;
  for (int k = 1; k * step <= eps0 * (1 + 1e-12); ++k) {
    const double level = k * step;
    const auto segments = level_line(area.grid.xi, area.grid.eta, area.grid.distance, level);
    if (segments.empty()) continue;
    const std::string name = format("level_%d.dat", k);
    auto out = job.open_data(name);
    out << "# eta[m] xi[m]: segments of the outline distance = " << level << " m\n";
    for (const auto& s : segments) out << s.y0 << " " << s.x0 << "\n" << s.y1 << " " << s.x1 << "\n\n";
    add_plot(plots, quoted(job.data_path(name)) +
                        format(" using ($1*1e3):($2*1e3) with lines lw 1.5 lc palette frac %.3f title 'ε0 = %.0f µm'",
                               (k - 1) / std::max(1.0, std::floor(eps0 / step + 1e-9) - 1), level * 1e6));
  }
}

// The Hertz ellipse at the common point for normal_force [N] (modulus E* [Pa]); a warning when
// Hertz has no ellipse there.
void add_hertz_ellipse(GnuplotJob& job, const ContactArea& area, double modulus, double normal_force,
                       std::string& plots) {
  const ContactModelOptions model_options;
  try {
    const PatchShape shape = contact_shape(area.common, model_options.lateral_curvature_floor);
    const HertzContact hertz = hertz_from_force(shape.shape, modulus, normal_force);
    auto out = job.open_data("hertz.dat");
    write_ellipse(out, hertz.a, hertz.b, 0, 0);
    add_plot(plots, quoted(job.data_path("hertz.dat")) +
                        format(" using ($1*1e3):($2*1e3) with lines lw 2.5 dt 2 lc rgb 'black' title 'Hertz ellipse "
                               "at P, N = %.0f kN (a = %.2f mm, b = %.2f mm)'",
                               normal_force * 1e-3, hertz.a * 1e3, hertz.b * 1e3));
  } catch (const std::exception& e) {
    std::cerr << "wrc plot area: no Hertz ellipse at the common point: " << e.what() << "\n";
  }
}

// The spline model's ellipse (fitted in-process) at its fitted contact point projected onto E.
void add_spline_ellipse(GnuplotJob& job, const WheelsetGeometry& geometry, const SplineFitOptions& fit_options,
                        WheelSide side, const ContactArea& area, double modulus, double normal_force,
                        std::string& plots) {
  const SplineFit fit = fit_spline_geometry(geometry, fit_options);
  const SplineContactGeometry& splines = *fit.model;
  if (!splines.inside(side, area.pose)) throw std::runtime_error("--spline: " + splines.outside_reason(side, area.pose));
  SplineEvaluation evaluation;
  splines.evaluate(side, area.pose, SplineDerivatives::kValue, evaluation);
  const ContactPoint fitted = splines.contact_point(side, area.pose, evaluation);
  const HertzContact hertz = hertz_from_force(splines.patch_shape(evaluation).shape, modulus, normal_force);
  const Eigen::Vector3d offset = fitted.wheel_point - area.origin;
  const double xi = offset.dot(area.t1), eta = offset.dot(area.t2);
  auto out = job.open_data("spline.dat");
  write_ellipse(out, hertz.a, hertz.b, xi, eta);
  add_plot(plots, quoted(job.data_path("spline.dat")) +
                      format(" using ($1*1e3):($2*1e3) with lines lw 2.5 dt 4 lc rgb '#9467bd' title 'spline model "
                             "ellipse (a = %.2f mm, b = %.2f mm, centre η = %.2f mm)'",
                             hertz.a * 1e3, hertz.b * 1e3, eta * 1e3));
}

int run_area(const std::vector<std::string>& args) {
  Options opt("plot area", "--y Y [--roll PHI] [--yaw PSI] [--wheel-side left|right] [--eps0 E] [--out FILE] [options]",
              area_option_specs(), args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe paper's figures 1-3, bottom: the wheel lowered onto the rail in the common point P; in the\n"
                 "common tangent plane E (xi rolling, eta lateral, towards +y) the outlines of the region where\n"
                 "the distance between the undeformed surfaces along the normal is below eps0 = 25, 50, ... um,\n"
                 "and the Hertz ellipse at P for --normal-force (material of the contact models). --spline adds the\n"
                 "ellipse of the spline model (fitted with the wrc fit options given) at its fitted contact point;\n"
                 "the pose must lie in the spline model's box (--box).\n";
    return 0;
  }
  const GeometrySpec spec = geometry_spec_from_options(opt);
  const WheelsetGeometry geometry = make_geometry(spec);
  const WheelsetPose pose = pose_from_options(opt, geometry.track().nominal_radius);
  const WheelSide side = side_from_options(opt);
  const double eps0 = opt.number("--eps0");
  const double normal_force = opt.number("--normal-force");
  ContactAreaOptions options;
  options.n_xi = options.n_eta = opt.integer("--grid");
  options.half_width_xi = options.half_width_eta = opt.number("--half-width");
  const bool with_spline = opt.has("--spline");
  const SplineFitOptions fit_options = fit_options_from(opt);
  const ImageRequest image = image_from_options(opt, "area.png");

  const ContactArea area = compute_contact_area(geometry, side, pose, options);
  GnuplotJob job;
  std::string plots;
  add_level_lines(job, area, eps0, plots);
  const ContactMaterial material;
  const double modulus = contact_modulus(material.shear_modulus, material.poisson_ratio);
  if (normal_force > 0) add_hertz_ellipse(job, area, modulus, normal_force, plots);
  if (with_spline && normal_force > 0)
    add_spline_ellipse(job, geometry, fit_options, side, area, modulus, normal_force, plots);
  {
    auto out = job.open_data("common.dat");
    out << "0 0\n";
  }
  add_plot(plots, quoted(job.data_path("common.dat")) + " using 1:2 with points pt 2 ps 2 lc rgb 'black' title 'common point P'");
  const std::string title = format("Contact area, %s wheel: ", side_name(side)) + geometry_title(spec) + "\n" +
                            pose_title(pose) +
                            format(", P at s = %.2f mm, contact angle %.2f°", area.common.s * 1e3,
                                   area.common.contact_angle * 180 / M_PI);
  std::string script = "set title " + quoted(title) + "\n";
  script += "set grid\nset size ratio -1\nset key below\nunset colorbox\n"
            "set palette defined (0 '#1f77b4', 0.5 '#2ca02c', 1 '#d62728')\n"
            "set xlabel 'lateral coordinate η in the tangent plane [mm]'\n"
            "set ylabel 'rolling coordinate ξ in the tangent plane [mm]'\n";
  script += "plot " + plots + "\n";
  job.render(script, image);
  return report_written(image);
}

const PlotKindRegistrar registrar{
    {"area", "contact area below eps0 in the common tangent plane with the Hertz ellipse (figures 1-3)", run_area, 2}};

}  // namespace
}  // namespace wrc::cli::plot
