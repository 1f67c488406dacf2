// SPDX-License-Identifier: Apache-2.0
// wrc area: the contact area of one wheel (the paper's figures 1-3): distances between the
// undeformed surfaces along the common normal on a grid of the common tangent plane.

#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/profile_options.hpp"
#include "core/geometry/contact_area.hpp"

namespace wrc::cli {
namespace {

void print_summary(const ContactArea& area, const std::vector<double>& thresholds) {
  const ContactPoint& p = area.common;
  std::printf("%s wheel, y = %.4f mm, roll = %.4f mrad, yaw = %.4f mrad\n", side_name(area.side), area.pose.y * 1e3,
              area.pose.roll * 1e3, area.pose.yaw * 1e3);
  std::printf("common point: s = %.4f mm, y = %.4f mm, contact angle = %.4f deg, normal = (%.5f, %.5f, %.5f)\n",
              p.s * 1e3, p.rail_point.y() * 1e3, p.contact_angle * 180 / M_PI, area.normal.x(), area.normal.y(),
              area.normal.z());
  std::printf("grid: %zu x %zu nodes, xi in [%.2f, %.2f] mm, eta in [%.2f, %.2f] mm (eta along t2 = n x t1, > 0 "
              "towards +y)\n",
              area.grid.xi.size(), area.grid.eta.size(), area.grid.xi.front() * 1e3, area.grid.xi.back() * 1e3,
              area.grid.eta.front() * 1e3, area.grid.eta.back() * 1e3);
  std::printf("local minima of the distance along C (s [mm], xi [mm], eta [mm], distance above P [um]):\n");
  for (const auto& m : area.minima)
    std::printf("  %10.4f %9.4f %9.4f %10.3f\n", m.s * 1e3, m.xi * 1e3, m.eta * 1e3, m.distance * 1e6);
  std::printf("%9s %11s %10s %10s %10s %10s %10s %10s %8s  %s\n", "eps0[um]", "area[mm2]", "xi_min", "xi_max",
              "eta_min", "eta_max", "xi_c", "eta_c", "patches", "patch eta ranges [mm] (* truncated)");
  for (double eps0 : thresholds) {
    const ContactAreaSummary s = area.summary(eps0);
    std::printf("%9.1f %11.4f %10.4f %10.4f %10.4f %10.4f %10.4f %10.4f %8d ", eps0 * 1e6, s.area * 1e6,
                s.xi_min * 1e3, s.xi_max * 1e3, s.eta_min * 1e3, s.eta_max * 1e3, s.xi_centroid * 1e3,
                s.eta_centroid * 1e3, s.patch_count());
    for (const auto& patch : s.patches)
      std::printf(" [%.3f, %.3f]%s", patch.eta_min * 1e3, patch.eta_max * 1e3, patch.truncated ? "*" : "");
    std::printf("\n");
  }
}

int run_area(const std::vector<std::string>& args) {
  auto specs = profile_option_specs();
  for (auto& spec : pose_option_specs()) specs.push_back(spec);
  specs.push_back(side_option_spec());
  specs.push_back({"--eps0", true, "threshold of the table's last row [m] (rows every 25 um up to it)", "1.5e-4",
      NumberRange{1e-9, 0.01}});
  specs.push_back({"--grid", true, "grid nodes per direction [-]", "61", NumberRange{2, 2001}});
  specs.push_back({"--half-width", true, "half width of the square grid in E [m]", "0.02", NumberRange{1e-6, 0.1}});
  specs.push_back({"--format", true, "csv (the grid) or table (summary)", "table"});
  Options opt("area", "--y Y [--roll PHI] [--yaw PSI] [--wheel-side left|right] [--eps0 E] [--grid N] "
              "[--half-width W] [--format csv|table] [options]", specs, args);
  if (opt.help_requested()) {
    std::cout << opt.help()
              << "\nThe contact area of the paper's figures 1-3. The wheel is lowered until it touches the rail in\n"
                 "the common point P; E is the common tangent plane through P with the common normal n (rail into\n"
                 "wheel), xi the rolling direction in E and eta = n x xi the lateral one (towards +y of the track).\n"
                 "distance = distance between the undeformed wheel and rail surfaces along n [m] (NaN where a\n"
                 "surface is missing). csv: one row xi,eta,distance per grid node (eta outer, xi inner).\n"
                 "table: area [mm^2], extents and centroid [mm] and the number of separate patches of the\n"
                 "region distance < eps0 for eps0 = 25, 50, ... um up to --eps0.\n";
    return 0;
  }
  const WheelsetGeometry geometry = geometry_from_options(opt);
  const WheelsetPose pose = pose_from_options(opt, geometry.track().nominal_radius);
  const WheelSide side = side_from_options(opt);
  const double eps0 = opt.number("--eps0");
  ContactAreaOptions options;
  options.n_xi = options.n_eta = opt.integer("--grid");
  options.half_width_xi = options.half_width_eta = opt.number("--half-width");
  const bool csv = opt.choice("--format", {"csv", "table"}) == "csv";

  const ContactArea area = compute_contact_area(geometry, side, pose, options);
  if (csv) {
    std::printf("xi,eta,distance\n");
    for (size_t j = 0; j < area.grid.eta.size(); ++j)
      for (size_t i = 0; i < area.grid.xi.size(); ++i)
        std::printf("%.9e,%.9e,%.9e\n", area.grid.xi[i], area.grid.eta[j], area.grid.at(i, j));
    return 0;
  }
  std::vector<double> thresholds;
  const double step = 25e-6;
  for (int k = 1; k * step <= eps0 * (1 + 1e-12); ++k) thresholds.push_back(k * step);
  if (thresholds.empty() || std::fabs(thresholds.back() - eps0) > 1e-12) thresholds.push_back(eps0);
  print_summary(area, thresholds);
  return 0;
}

const CommandRegistrar registrar{{"area", "contact area of one wheel in the common tangent plane", run_area}};

}  // namespace
}  // namespace wrc::cli
