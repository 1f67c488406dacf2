// SPDX-License-Identifier: Apache-2.0
// Linear stability of a vehicle (core/vehicle_dynamics/vehicle_linear_stability.hpp): against the
// lone wheelset's own analysis (core/dynamics/linear_stability.hpp, validated in
// dynamics_linear_stability_test.cpp against the classical closed form), and against the vehicle's
// own nonlinear run, which must decay at the rate and frequency of its least damped mode.
#include "core/vehicle_dynamics/vehicle_linear_stability.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/single_wheelset_vehicle.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "cone_on_circle.hpp"
#include "expect_invalid.hpp"

namespace wrc {
namespace {

// A cone of conicity 0.05 on a 0.1 m circular rail head, gauge 1.5 m, with radius r0 [m].
std::shared_ptr<ContactEvaluator> cone_contact(const std::string& model, double r0) {
  return std::make_shared<InProcessContact>(make_contact_model(model, test::cone_on_circle("0.05", r0)));
}

VehicleDescription shipped(const std::string& name) {
  return read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/" + name + ".json");
}

// The benchmark's wheelset (parameters/vehicles/single-wheelset.json) without its lateral load,
// its axle boxes relaxed at the height where it stands on the cone (as the lone wheelset's
// suspension is: at the centred wheelset's height in contact), friction 10.
VehicleRunSpec single_wheelset(double r0) {
  VehicleRunSpec spec;
  spec.vehicle = shipped("single-wheelset");
  spec.vehicle.bodies[0].external_force[1] = 0.0;
  spec.run.wheelset.material.friction = 10.0;
  VehicleLinearStability first(spec, cone_contact("onepoint", r0), r0);
  const double z = first.linearise(30.0).rest_state[kUnknownZ];
  spec.vehicle.bodies[0].position[2] = z;
  for (VehicleElement& e : spec.vehicle.elements) e.attachments[1][2] = z;
  return spec;
}

// The vehicle file of one wheelset is the lone wheelset: the same eigenvalues, rigid (5: y, yaw,
// their rates, the spin; the constraints' 8 infinite ones left out) and elastic (9, with the
// vertical and roll modes on the Hertz springs). Both take forward differences of the residual for
// their Jacobian... the wheelset's central ones: the difference is the forward differences'
// truncation, h f''/2 with h = 1e-7 of the unknown: 6e-6 of the lateral modes measured, 5e-5 of
// the Hertz springs' frequencies (their force goes with the approach^1.5, whose second derivative
// is large at an approach of 0.1 mm). Tolerance 1e-4 of |lambda|; a lost term of the equations
// (a spring, the gyroscopic coupling) moves an eigenvalue by percents.
TEST(VehicleLinearStability, TheSingleWheelsetFileHasTheLoneWheelsetsEigenvalues) {
  constexpr double kR0 = 0.46;
  const VehicleRunSpec spec = single_wheelset(kR0);
  WheelsetParameters p = spec.run.wheelset;
  apply_single_wheelset(spec.vehicle, p);
  for (const char* model : {"onepoint", "multipoint"}) {
    VehicleLinearStability vehicle(spec, cone_contact(model, kR0), kR0);
    LinearStability wheelset(p, cone_contact(model, kR0), kR0);
    for (double v : {30.0, 80.0}) {
      SCOPED_TRACE(std::string(model) + " at " + std::to_string(v) + " m/s");
      const LinearisedVehicle a = vehicle.linearise(v);
      const LinearisedWheelset b = wheelset.linearise(v);
      ASSERT_EQ(a.modes.size(), b.modes.size());
      for (size_t k = 0; k < a.modes.size(); ++k) {
        EXPECT_LE(std::abs(a.modes[k].eigenvalue - b.modes[k].eigenvalue), 1e-4 * std::abs(b.modes[k].eigenvalue))
            << k << ": " << a.modes[k].eigenvalue << " vs " << b.modes[k].eigenvalue;
        EXPECT_EQ(a.modes[k].kind, b.modes[k].kind) << k;
      }
    }
  }
}

// The growth rate [1/s] and frequency [Hz] of the oscillation y(t) sampled at t after t_from [s]:
// from its successive maxima (a parabola through each maximum and its neighbours), the log
// decrement over the span of all of them.
std::pair<double, double> decay_of(const std::vector<double>& t, const std::vector<double>& y, double t_from) {
  std::vector<double> peak_t, peak_y;
  for (size_t i = 1; i + 1 < y.size(); ++i) {
    if (t[i] < t_from || !(y[i] > y[i - 1] && y[i] >= y[i + 1])) continue;
    const double h = t[i + 1] - t[i];
    const double a = 0.5 * (y[i + 1] - 2.0 * y[i] + y[i - 1]), b = 0.5 * (y[i + 1] - y[i - 1]);
    const double shift = -b / (2.0 * a);
    peak_t.push_back(t[i] + shift * h);
    peak_y.push_back(y[i] + b * shift + a * shift * shift);
  }
  if (peak_t.size() < 3) throw std::runtime_error("fewer than 3 maxima");
  const size_t n = peak_t.size() - 1;
  const double span = peak_t[n] - peak_t[0];
  return {std::log(peak_y[n] / peak_y[0]) / span, static_cast<double>(n) / span};
}

// "Same growth, in motion": the Cooperrider bogie on a cone of conicity 0.2 (critical speed
// 82.0 m/s, its trailing wheelset hunting at 10.4 Hz) at 1.1 times its critical speed, its leading
// wheelset held 1 um off the centre and released, grows as its least damped mode says. From 1 s on
// (the other excited modes, damped at 1.6 1/s and more, then below 1/30 of it, 1/1000 at the end)
// the maxima of the trailing wheelset's y up to 2.5 s (1.5 mm) give the growth rate and frequency.
// What differs: the cone's geometry is linear to 4 digits over 2 mm, FASTSIM at friction 10 is
// linear to u/3 = 1e-3; each maximum's parabola at 1 ms samples is exact to (omega h)^2 / 12 =
// 4e-4. Tolerance: 3 % of the growth rate (the others' remains: 1/30 at the start of the window
// over a growth of 4.5 e-folds), 0.5 % of the frequency; a lost factor 2 in a damper or a creep
// coefficient moves them by tens of percent, the wrong mode by more.
TEST(VehicleLinearStability, TheBogieGrowsAtTheRateOfItsLeastDampedMode) {
  constexpr double kR0 = 0.425;
  VehicleRunSpec spec;
  spec.vehicle = shipped("cooperrider-bogie");
  spec.run.wheelset.material.friction = 10.0;
  const auto contact = std::make_shared<InProcessContact>(make_contact_model("onepoint", test::cone_on_circle("0.2", kR0)));
  VehicleLinearStability stability(spec, contact, kR0);
  std::vector<LinearisedVehicle> scan;
  for (double v : stability_speeds(70.0, 100.0, 10.0)) scan.push_back(stability.linearise(v));
  const VehicleCriticalSpeed critical = stability.critical_speed(scan);
  ASSERT_TRUE(critical.found);
  EXPECT_NEAR(critical.speed, 82.0, 0.5);
  EXPECT_EQ(critical.mode.body, 2u);  // the trailing wheelset
  const double speed = 1.1 * critical.speed;
  const VehicleMode mode = stability.linearise(speed).least_damped();
  ASSERT_GT(mode.eigenvalue.real(), 0.0);
  spec.run.wheelset.speed = speed;
  spec.run.initial.y = 1e-6;
  spec.run.integrator.t_end = 2.5;
  VehicleSimulation run(spec, contact, kR0);
  std::vector<double> time, y;
  run.on_output([&](const VehicleSnapshot& s) {
    time.push_back(s.t);
    y.push_back(s.bodies[2].displacement[kBodyLateral]);
  });
  run.run();
  ASSERT_EQ(run.state(), RunState::kFinished) << run.message();
  const auto [growth, frequency] = decay_of(time, y, 1.0);
  EXPECT_NEAR(growth, mode.eigenvalue.real(), 0.03 * mode.eigenvalue.real());
  EXPECT_NEAR(frequency, mode.frequency(), 5e-3 * mode.frequency());
}

// A vehicle the analysis cannot take is refused naming what.
TEST(VehicleLinearStability, WhatTheAnalysisCannotTakeIsRefused) {
  VehicleRunSpec spec;
  spec.vehicle = shipped("single-wheelset");  // its 20 kN lateral load
  const auto contact = cone_contact("onepoint", 0.46);
  test::expect_invalid([&] { VehicleLinearStability(spec, contact, 0.46); }, "lateral force");
  spec.vehicle.bodies[0].external_force[1] = 0.0;
  spec.run.track = TrackLayout({TrackSegment{TrackSegmentKind::kCurve, 100.0, 1000.0, true, 0.0}});
  test::expect_invalid([&] { VehicleLinearStability(spec, contact, 0.46); }, "straight");
  spec.run.track = TrackLayout();
  VehicleLinearStability s(spec, contact, 0.46);
  test::expect_invalid([&] { s.linearise(-5.0); }, "-5");
}

}  // namespace
}  // namespace wrc
