// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Test support: the vehicle file of one wheelset (parameters/vehicles/single-wheelset.json) run on
/// the vehicle's equations next to the lone wheelset's run from the same state, on S1002/UIC60:
/// the reference a vehicle's switches and swaps are compared with; and the Cooperrider bogie's run
/// they are tried on.

#include <memory>
#include <string>

#include "core/dynamics/single_wheelset_vehicle.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "spline_test_model.hpp"

namespace wrc::test {

/// A shipped vehicle file by name (parameters/vehicles/NAME.json).
inline VehicleDescription shipped_vehicle(const std::string& name) {
  return read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/" + name + ".json");
}

/// S1002 of nominal radius r0 [m] on UIC60 1:40, standard gauge.
inline std::shared_ptr<const WheelsetGeometry> s1002_uic60(double r0) {
  if (r0 == 0.46) return s1002_uic60_geometry();
  TrackParameters track;
  track.nominal_radius = r0;
  return std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                  make_profile("UIC60", ProfileSide::kRail), track);
}

/// Model `model` (not spline) on s1002_uic60(r0), in-process.
inline std::shared_ptr<ContactEvaluator> s1002_contact(const std::string& model, double r0) {
  return std::make_shared<InProcessContact>(make_contact_model(model, s1002_uic60(r0)));
}

/// The single-wheelset file's run at speed [m/s] to t_end [s], released y0 [m] off the centre, the
/// lateral load 0, its axle boxes relaxed at the height where the centred wheelset stands on
/// S1002/UIC60 (r0 0.46 m; as the lone wheelset's suspension is).
inline VehicleRunSpec single_wheelset_run(double speed, double y0, double t_end) {
  constexpr double r0 = 0.46;
  VehicleRunSpec spec;
  spec.vehicle = shipped_vehicle("single-wheelset");
  spec.vehicle.bodies[0].external_force[1] = 0.0;
  spec.run.integrator.t_end = t_end;
  spec.run.wheelset.speed = speed;
  VehicleSimulation centred(spec, s1002_contact("onepoint", r0), r0);
  centred.start();
  const WheelsetSnapshot rest = centred.wheelset_snapshot(centred.snapshot(), 0);
  spec.vehicle.bodies[0].position[2] = rest.z;
  for (VehicleElement& e : spec.vehicle.elements) e.attachments[1][2] = rest.z;
  spec.run.initial.y = y0;
  return spec;
}

/// The lone wheelset's run of the same file and settings (the wheelset's parameters from the file,
/// apply_single_wheelset()), from y0 with the spin the vehicle's rest gave its wheelset
/// (spin_rate [rad/s]).
inline RunSpec lone_run_of(const VehicleRunSpec& vehicle, double spin_rate) {
  RunSpec lone;
  lone.wheelset = vehicle.run.wheelset;
  apply_single_wheelset(vehicle.vehicle, lone.wheelset);
  lone.integrator = vehicle.run.integrator;
  lone.initial.y = vehicle.run.initial.y;
  lone.initial.spin_rate_offset = spin_rate - lone.wheelset.speed / 0.46;
  return lone;
}

/// The Cooperrider bogie (parameters/vehicles/cooperrider-bogie.json) on S1002/UIC60 of r0 0.425 m,
/// friction 0.15, at speed [m/s] to t_end [s], its leading wheelset released y0 [m] off the centre.
inline VehicleRunSpec cooperrider_bogie_run(double speed, double y0, double t_end) {
  VehicleRunSpec spec;
  spec.vehicle = shipped_vehicle("cooperrider-bogie");
  spec.run.wheelset.material.friction = 0.15;
  spec.run.wheelset.speed = speed;
  spec.run.initial.y = y0;
  spec.run.integrator.t_end = t_end;
  return spec;
}

}  // namespace wrc::test
