// SPDX-License-Identifier: Apache-2.0
#include "cli/vehicle_stability.hpp"

#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/in_process_contact.hpp"
#include "options/fit_options.hpp"
#include "cli/plot/plot_options.hpp"
#include "cli/profile_options.hpp"
#include "cli/run_options.hpp"
#include "cli/stability_report.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle_dynamics/vehicle_linear_stability.hpp"
#include "options/parameter_options.hpp"

namespace wrc::cli {
namespace {

// The run's common values (speed, material, FASTSIM grid, gravity, tolerances) from --params and
// the parameter options; an option the vehicle file gives is refused.
RunSpec vehicle_run_spec(const Options& o) {
  refuse_options_a_vehicle_gives(o);
  RunSpec spec;
  if (o.has("--params")) apply_run_parameter_file(o.text("--params"), spec);
  apply_parameter_options(wheelset_parameter_table(), o, spec.wheelset);
  return spec;
}

StabilityScanRow row_of(const LinearisedVehicle& l, const VehicleDescription& vehicle) {
  StabilityScanRow row;
  row.speed = l.speed;
  for (const VehicleMode& m : l.modes) {
    row.modes.push_back({m.eigenvalue, m.kind});
    row.bodies.push_back(vehicle.bodies[m.body].name);
  }
  return row;
}

// The vehicle's linear critical speed found in a scan, in the lone wheelset's terms.
CriticalSpeed critical_speed_from(const VehicleCriticalSpeed& found) {
  CriticalSpeed critical;
  critical.found = found.found;
  critical.speed = found.speed;
  critical.frequency = found.mode.frequency();
  critical.kind = found.mode.kind;
  return critical;
}

}  // namespace

CriticalSpeed linear_critical_speed(const RunSpec& spec, const std::optional<VehicleDescription>& vehicle,
                                    std::shared_ptr<ContactEvaluator> contact, double r0,
                                    const std::vector<double>& speeds) {
  if (vehicle) {
    VehicleLinearStability stability(VehicleRunSpec{*vehicle, spec, std::nullopt}, std::move(contact), r0);
    std::vector<LinearisedVehicle> scan;
    for (double v : speeds) scan.push_back(stability.linearise(v));
    return critical_speed_from(stability.critical_speed(scan));
  }
  LinearStability stability(spec.wheelset, std::move(contact), r0);
  std::vector<LinearisedWheelset> scan;
  for (double v : speeds) scan.push_back(stability.linearise(v));
  return stability.critical_speed(scan);
}

int run_vehicle_stability(const Options& o, const VehicleDescription& vehicle, const std::string& vehicle_path,
                          const std::string& model, const std::vector<double>& speeds, const std::string& csv,
                          const std::string& picture) {
  VehicleRunSpec spec;
  spec.vehicle = vehicle;
  spec.run = vehicle_run_spec(o);
  const GeometrySpec geometry_spec = geometry_spec_from_options(o);
  const auto geometry = std::make_shared<const WheelsetGeometry>(make_geometry(geometry_spec));
  const double r0 = geometry_spec.track.nominal_radius;
  if (contact_model_entry(model).needs_data)
    std::cerr << "fitting the spline model (in-process, as wrc run --in-process does) ...\n";
  VehicleLinearStability stability(spec, in_process_contact(model, geometry, fit_options_from(o)), r0);
  std::printf("vehicle: '%s' (%s), %zu bodies, %zu wheelsets\n", vehicle.name.c_str(), vehicle_path.c_str(),
              vehicle.bodies.size(), vehicle.wheelsets().size());
  std::printf("linear stability, %s contact (%s formulation), %s\n", model.c_str(),
              contact_model_entry(model).dynamics_formulation == ContactFormulation::kRigid ? "rigid" : "elastic",
              plot::geometry_title(geometry_spec).c_str());
  std::printf("%10s %14s %12s %12s  %-15s %s\n", "V [m/s]", "real [1/s]", "freq [Hz]", "damping [-]", "mode", "body");
  std::vector<LinearisedVehicle> scan;
  std::vector<StabilityScanRow> rows;
  for (double v : speeds) {
    scan.push_back(stability.linearise(v));
    rows.push_back(row_of(scan.back(), vehicle));
    const VehicleMode& m = scan.back().least_damped();
    std::printf("%10.4g %14.6g %12.5g %12.5g  %-15s %s (%.0f %%)\n", v, m.eigenvalue.real(), m.frequency(),
                m.damping_ratio(), mode_kind_name(m.kind), vehicle.bodies[m.body].name.c_str(), 100.0 * m.body_share);
  }
  const VehicleCriticalSpeed found = stability.critical_speed(scan);
  const CriticalSpeed critical = critical_speed_from(found);
  if (found.found)
    std::printf("linear critical speed: %.4f m/s (%.1f km/h), frequency %.4f Hz (%s mode, mostly %s)\n", found.speed,
                found.speed * 3.6, found.mode.frequency(), mode_kind_name(found.mode.kind),
                vehicle.bodies[found.mode.body].name.c_str());
  else
    std::printf("linear critical speed: none in %g..%g m/s (largest real part %s 0 throughout)\n", speeds.front(),
                speeds.back(), scan.front().least_damped().eigenvalue.real() < 0 ? "below" : "at or above");
  write_stability_csv(csv, rows);
  std::cout << "wrote " << csv << "\n";
  draw_stability(picture, rows, critical,
                 "wrc stability: " + vehicle.name + ", " + model + " contact, " + plot::geometry_title(geometry_spec));
  std::cout << "wrote " << picture << "\n";
  return 0;
}

}  // namespace wrc::cli
