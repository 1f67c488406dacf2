// SPDX-License-Identifier: Apache-2.0
// wrc stability: linear stability of the wheelset on straight track (core/dynamics/
// linear_stability.hpp, docs/stability.md), in-process with the chosen contact model: the
// eigenvalues against speed, the least damped mode per speed, the linear critical speed with its
// frequency, a CSV of every eigenvalue and the eigenvalue plot (root locus, largest real part
// against speed), and the classical model (Wickens) built from the same contact for comparison.
// With --vehicle FILE of several bodies: the vehicle's (cli/vehicle_stability.hpp).

#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

#include "cli/centred_run_options.hpp"
#include "cli/run_options.hpp"
#include "cli/command.hpp"
#include "cli/in_process_contact.hpp"
#include "options/fit_options.hpp"
#include "cli/options.hpp"
#include "cli/output_paths.hpp"
#include "cli/plot/gnuplot_job.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/profile_options.hpp"
#include "cli/speed_scan_option.hpp"
#include "cli/stability_report.hpp"
#include "cli/vehicle_stability.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/dynamics/wickens_from_model.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "options/parameter_options.hpp"

namespace wrc::cli {
namespace {

int run_stability(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs{
      {"--model", true, "contact model: onepoint, interp, multipoint or spline", ""},
      {"--speeds", true, "speeds FROM:TO:STEP [m/s]", "5:80:1"},
      {"--out", true, "every eigenvalue at every speed (CSV, units in the header)", "stability.csv"},
      {"--plot", true, "the eigenvalue plot (.png or .svg)", "stability.png"},
  };
  const std::vector<OptionSpec> sources = wheelset_source_option_specs();
  specs.insert(specs.begin() + 2, sources.begin(), sources.end());
  for (auto& spec : parameter_option_specs(wheelset_parameter_table(), WheelsetParameters{})) specs.push_back(spec);
  for (auto& spec : profile_option_specs()) specs.push_back(spec);
  for (auto& spec : spline_model_fit_option_specs()) specs.push_back(spec);
  const Options o("stability", "--model M [--speeds 5:80:1] [--out FILE.csv] [--plot FILE.png] [options]", specs, args);
  if (o.help_requested()) {
    std::cout << o.help()
              << "\nLinearises the wheelset's equations (those wrc run integrates, with contact model M, in-process)\n"
                 "about the centred steady state on straight track at each speed, prints the least damped\n"
                 "eigenvalue per speed and the linear critical speed (largest real part crossing 0) with its\n"
                 "frequency, and the classical model (Wickens) built from the same contact. The lateral load is\n"
                 "set to 0: a centred steady state has none (an explicit non-zero --lateral-force is refused).\n"
                 "docs/stability.md.\n";
    return 0;
  }
  const std::string model = o.choice("--model", contact_model_names());
  if (model.empty()) throw UsageError("--model is required (onepoint, interp, multipoint or spline)");
  const std::vector<double> speeds = parse_speed_scan(o.text("--speeds", "5:80:1"), "--speeds");
  const std::string csv = o.text("--out", "stability.csv");
  const std::string picture = o.text("--plot", "stability.png");
  check_output_path(csv, "--out");
  plot::image_request(picture, 1400, 700);  // checks the extension and the path before the work
  if (o.has("--vehicle")) {
    // A vehicle of several bodies takes the vehicle's equations; one wheelset, the wheelset's.
    const std::string path = o.text("--vehicle");
    VehicleDescription vehicle;
    try {
      vehicle = read_vehicle_file(path);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--vehicle: ") + e.what());
    }
    if (vehicle.bodies.size() > 1) return run_vehicle_stability(o, vehicle, path, model, speeds, csv, picture);
  }
  const RunSpec spec = centred_run_spec(o, "a centred steady state has no lateral load");

  const GeometrySpec geometry_spec = geometry_spec_from_options(o);
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(geometry_spec));
  const double r0 = geometry_spec.track.nominal_radius;
  if (contact_model_entry(model).needs_data)
    std::cerr << "fitting the spline model (in-process, as wrc run --in-process does) ...\n";
  LinearStability stability(spec.wheelset, in_process_contact(model, geometry, fit_options_from(o)), r0);

  std::printf("linear stability, %s contact (%s formulation), %s\n", model.c_str(),
              stability.formulation() == ContactFormulation::kRigid ? "rigid" : "elastic",
              plot::geometry_title(geometry_spec).c_str());
  std::printf("%10s %14s %12s %12s  %s\n", "V [m/s]", "real [1/s]", "freq [Hz]", "damping [-]", "mode");
  std::vector<LinearisedWheelset> scan;
  for (double v : speeds) {
    scan.push_back(stability.linearise(v));
    const StabilityMode& m = scan.back().least_damped();
    std::printf("%10.4g %14.6g %12.5g %12.5g  %s\n", v, m.eigenvalue.real(), m.frequency(), m.damping_ratio(),
                mode_kind_name(m.kind));
  }
  const CriticalSpeed critical = stability.critical_speed(scan);
  if (critical.found)
    std::printf("linear critical speed: %.4f m/s (%.1f km/h), frequency %.4f Hz (%s mode)\n", critical.speed,
                critical.speed * 3.6, critical.frequency, mode_kind_name(critical.kind));
  else
    std::printf("linear critical speed: none in %g..%g m/s (largest real part %s 0 throughout)\n", speeds.front(),
                speeds.back(), scan.front().least_damped().eigenvalue.real() < 0 ? "below" : "at or above");

  // The classical model from the same contact (its centred patch, conicity, gravitational stiffness).
  const WickensFromModel w = wickens_from_model(*geometry, spec.wheelset, scan.front().steady);
  std::printf("classical model (Wickens; docs/stability.md) from this contact: lambda = %.5g, r0 = %.5g m, b0 = %.5g m,\n"
              "  a = %.4g mm, b = %.4g mm, f11 = %.5g MN, f22 = %.5g MN per wheel, k_y = %.5g MN/m (gravitational %.5g),\n"
              "  k_psi = %.5g MN m/rad (gravitational %.5g)\n",
              w.model.conicity, w.model.rolling_radius, w.model.contact_half_distance, w.semi_axis_a * 1e3,
              w.semi_axis_b * 1e3, w.model.f11 * 1e-6, w.model.f22 * 1e-6, w.model.lateral_stiffness * 1e-6,
              w.gravitational_stiffness * 1e-6, w.model.yaw_stiffness * 1e-6, w.gravitational_yaw_stiffness * 1e-6);
  if (const auto c = w.model.critical_point())
    std::printf("  its critical speed without dampers: %.4f m/s, %.4f Hz%s\n", c->speed, c->frequency(),
                w.model.lateral_damping > 0 || w.model.yaw_damping > 0 ? " (this wheelset has dampers)" : "");
  else
    std::printf("  its critical speed without dampers: none\n");

  std::vector<StabilityScanRow> rows;
  for (const LinearisedWheelset& l : scan) rows.push_back({l.speed, l.modes, {}});
  write_stability_csv(csv, rows);
  std::cout << "wrote " << csv << "\n";
  draw_stability(picture, rows, critical, "wrc stability: " + model + " contact, " + plot::geometry_title(geometry_spec));
  std::cout << "wrote " << picture << "\n";
  return 0;
}

const CommandRegistrar registrar{{"stability",
                                  "linear stability on straight track: eigenvalues against speed, critical speed, plot",
                                  run_stability}};

}  // namespace
}  // namespace wrc::cli
