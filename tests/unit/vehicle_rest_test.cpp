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
#include <memory>
#include <string>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
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

}  // namespace
}  // namespace wrc
