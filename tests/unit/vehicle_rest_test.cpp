// SPDX-License-Identifier: Apache-2.0
// The Manchester coach (parameters/vehicles/manchester-coach.json) at rest on S1002/UIC60 1:40,
// checked against its statics by hand (docs/vehicle.md, "The Manchester coach"):
// - the wheels carry the whole weight, (32000 + 2 x 2615 + 4 x 1813) kg x g, and, the coach being
//   symmetric fore and aft and left and right, each wheel an eighth of it, 54.55 kN (Q, the rail's
//   vertical force on the wheel: the normal force is 0.02 % less, the creep forces on the inclined
//   contact plane carrying the rest);
// - the springs carry what lies above them: each primary spring a quarter of a bogie frame and half
//   a car body, (2615 + 16000) kg x g / 4 = 45.65 kN, so the frames sink 45.65 kN / 1.2e6 N/m =
//   38.04 mm on their wheelsets; each secondary spring a quarter of the car body, 78.48 kN, so the
//   car body sinks 78.48 kN / 4.3e5 N/m = 182.5 mm more;
// - nothing moves laterally, rolls or yaws.
// The wheelsets stand on their rails (the rigid contact's constraint), so the frames' and car
// body's vertical displacements are the wheelsets' plus the spring deflections, to the Newton
// tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/track/irregularity_spectrum.hpp"
#include "core/track/track_layout_file.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "coach_on_track.hpp"
#include "single_wheelset_vehicle_run.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // [m] S1002's nominal radius in the default geometry, the coach's axle height
constexpr double kG = 9.81;   // [m/s^2] the run parameters' gravity

TEST(VehicleRest, TheManchesterCoachRestsOnItsSpringsAsItsStaticsSay) {
  VehicleRunSpec spec;
  spec.vehicle = read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/manchester-coach.json");
  spec.run.wheelset.speed = 30.0;
  spec.run.wheelset.lateral_force = 0.0;
  ASSERT_EQ(spec.run.wheelset.gravity, kG);
  auto contact = std::make_shared<InProcessContact>(make_contact_model("onepoint", test::s1002_uic60_geometry()));
  VehicleSimulation run(spec, contact, kR0);
  run.start();
  const VehicleSnapshot rest = run.snapshot();
  const double weight = (32000.0 + 2 * 2615.0 + 4 * 1813.0) * kG;
  double sum = 0.0;
  for (size_t w = 0; w < 4; ++w)
    for (const WheelOutput& wheel : run.last_step_wheels(w)) {
      sum += wheel.vertical_force;
      EXPECT_NEAR(wheel.vertical_force, weight / 8.0, 1e-7 * weight);
    }
  EXPECT_NEAR(sum, weight, 1e-7 * weight);
  const double primary = (2615.0 + 16000.0) * kG / 4.0 / 1.2e6;  // [m] 38.04 mm
  const double secondary = 32000.0 * kG / 4.0 / 4.3e5;          // [m] 182.5 mm
  // Every wheelset stands on its rails at the centred wheelset's height, which differs from r0 by
  // the profiles' shape near the rolling circle (tenths of a millimetre); the bodies above sink
  // from there.
  const double axle = rest.bodies[run.equations().wheelset_body(0)].displacement[kBodyVertical];
  EXPECT_LT(std::abs(axle), 1e-3);
  const auto& names = spec.vehicle.bodies;
  for (size_t b = 0; b < names.size(); ++b) {
    const BodyState& s = rest.bodies[b];
    double expected = axle;
    if (names[b].kind == BodyKind::kBogieFrame) expected = axle - primary;
    if (names[b].kind == BodyKind::kCarBody) expected = axle - primary - secondary;
    const double vertical = s.displacement[kBodyVertical];
    EXPECT_NEAR(vertical, expected, 1e-7) << names[b].name;
    EXPECT_NEAR(s.displacement[kBodyLateral], 0.0, 1e-9) << names[b].name;
    EXPECT_NEAR(s.displacement[kBodyRoll], 0.0, 1e-9) << names[b].name;
    EXPECT_NEAR(s.displacement[kBodyYaw], 0.0, 1e-9) << names[b].name;
  }
}

// On irregular rails a model's Newton iteration from the nominal positions may not find the rest
// (the multipoint model on these, seed 2: the elastic stage's first steps sink a wheel 50 mm into
// its rail, which Hertz's theory refuses). The rest is then continued from the nominal rails, the
// irregularities' share raised from 0 to 1. What comes out must be the equilibrium on the whole
// irregularities: Newton started there converges at once (one iteration, a step below 1e-3 of the
// tolerances), not one on a share of them (a share of 0.9 moves the wheelsets by tenths of a
// millimetre, thousands of tolerances).
TEST(VehicleRest, OnIrregularRailsTheRestIsContinuedFromTheNominalRails) {
  const VehicleRunSpec spec = test::coach_on_irregular_track(2);
  const std::vector<double> loads = static_wheel_loads(spec.vehicle, spec.run.wheelset.gravity);
  VehicleEquations equations(spec.vehicle, spec.run.wheelset, spec.run.track, spec.run.irregularity, kR0, loads);
  VehicleContact contact(std::make_shared<InProcessContact>(make_contact_model("multipoint", test::s1002_uic60_geometry())),
                         equations, true);
  VehicleDae dae(equations, contact);
  const std::vector<double> rest = vehicle_rest_state(dae, ContactFormulation::kElastic, 0.0, 1e-8, 1e-6);
  const VehicleEquilibrium again = vehicle_equilibrium(dae, 0.0, rest, equilibrium_weights(dae, 1e-8, 1e-6));
  EXPECT_LE(again.iterations, 1);
  EXPECT_LT(again.last_step, 1e-3);
  // Each front wheelset stands where the irregularities (faded in over the first 20 m) put its rails.
  const std::vector<BodyState> bodies = equations.body_states(dae.layout(), rest.data());
  const IrregularityPoint at_leading = spec.run.irregularity.at(spec.vehicle.bodies[equations.wheelset_body(0)].position[0]);
  EXPECT_NEAR(bodies[equations.wheelset_body(0)].displacement[kBodyLateral], at_leading.alignment, 3e-3);
}

// A rigid one-point model may have no rest at all on irregular rails: a wheel at rest where its
// contact point jumps (the coach on these, seed 1: the continuation stops at a quarter of the
// irregularities). The run then starts from the rest on the nominal rails with each wheelset
// placed onto its rails (positions and velocities projected, derivatives consistent), says so,
// and runs: every wheel loaded at the start, the run to 0.2 s.
TEST(VehicleRest, ARigidRunWithNoRestOnItsRailsStartsPlacedOnThemAndSaysSo) {
  VehicleRunSpec spec = test::coach_on_irregular_track(1);
  spec.run.integrator.t_end = 0.2;
  VehicleSimulation sim(spec, std::make_shared<InProcessContact>(make_contact_model("onepoint", test::s1002_uic60_geometry())),
                        kR0);
  sim.start();
  EXPECT_NE(sim.start_note().find("started off its equilibrium"), std::string::npos) << sim.start_note();
  for (size_t w = 0; w < 4; ++w)
    for (const WheelOutput& wheel : sim.last_step_wheels(w)) EXPECT_GT(wheel.normal_force, 0.0) << "wheelset " << w;
  sim.run();
  EXPECT_EQ(sim.state(), RunState::kFinished) << sim.message();
}

// A start held off centre (a hunting run's disturbance) may have no rest reachable by Newton from
// the nominal positions: the Cooperrider bogie with its leading wheelset held 4 mm off centre puts
// the trailing one near a jump of its contact point (S1002/UIC60: the rigid stage of the multipoint
// model's rest does not converge there). The rest is then continued from the centred rest, the
// hold's offset raised from 0 to 4 mm in the elastic formulation, which is smooth. What comes out
// must be the equilibrium with the whole offset held: Newton started there converges at once, and
// the leading wheelset stands at 4 mm.
TEST(VehicleRest, ABogieHeldOffCentreRestsByContinuationFromTheCentredRest) {
  constexpr double r0 = 0.425, y0 = 4e-3;  // [m] the bogie's wheels; [m] the hold
  const VehicleRunSpec spec = test::cooperrider_bogie_run(95.0, y0, 0.1);
  const std::vector<double> loads = static_wheel_loads(spec.vehicle, spec.run.wheelset.gravity);
  VehicleEquations equations(spec.vehicle, spec.run.wheelset, spec.run.track, spec.run.irregularity, r0, loads);
  VehicleContact contact(test::s1002_contact("multipoint", r0), equations, true);
  VehicleDae dae(equations, contact);
  const std::vector<HeldWheelset> held{{0, y0, 0.0}};
  const std::vector<double> rest = vehicle_rest_state(dae, ContactFormulation::kElastic, 0.0, 1e-8, 1e-6, held);
  const VehicleEquilibrium again = vehicle_equilibrium(dae, 0.0, rest, equilibrium_weights(dae, 1e-8, 1e-6), held);
  EXPECT_LE(again.iterations, 1);
  EXPECT_LT(again.last_step, 1e-3);
  const std::vector<BodyState> bodies = equations.body_states(dae.layout(), rest.data());
  EXPECT_NEAR(bodies[equations.wheelset_body(0)].displacement[kBodyLateral], y0, 1e-9);
  // The trailing wheelset follows the leading one through the frame, part of the way.
  const double trailing = bodies[equations.wheelset_body(1)].displacement[kBodyLateral];
  EXPECT_GT(trailing, 0.0);
  EXPECT_LT(trailing, y0);
}

// The rigid one-point model has no rest at all with that hold: the continuation stops where the
// trailing wheelset stands at its contact point's jump (a third of the way). The run then starts
// from the centred rest with the leading wheelset moved to its hold and every wheelset placed onto
// its rails, says so, and runs: the leading wheelset at 4 mm, every wheel loaded, the run to its end.
TEST(VehicleRest, ARigidBogieHeldWhereItHasNoRestStartsMovedToItsHoldAndSaysSo) {
  constexpr double r0 = 0.425, y0 = 4e-3;
  VehicleSimulation sim(test::cooperrider_bogie_run(95.0, y0, 0.05), test::s1002_contact("onepoint", r0), r0);
  sim.start();
  EXPECT_NE(sim.start_note().find("first wheelset then moved to its held y and yaw"), std::string::npos)
      << sim.start_note();
  EXPECT_NEAR(sim.wheelset_snapshot(sim.snapshot(), 0).y, y0, 1e-9);
  for (size_t w = 0; w < 2; ++w)
    for (const WheelOutput& wheel : sim.last_step_wheels(w)) EXPECT_GT(wheel.normal_force, 0.0) << "wheelset " << w;
  sim.run();
  EXPECT_EQ(sim.state(), RunState::kFinished) << sim.message();
}

}  // namespace
}  // namespace wrc
