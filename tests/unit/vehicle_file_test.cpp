// SPDX-License-Identifier: Apache-2.0
// The vehicle file (core/vehicle/vehicle_file.hpp): the shipped parameter sets read and hold what
// their sources say (masses, the Cooperrider car's static wheel load), and every kind of bad file
// is refused in one line naming the file, the body or element and the key.
#include "core/vehicle/vehicle_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace wrc {
namespace {

const std::string kDir = std::string(WRC_PARAMETERS_DIR) + "/vehicles/";

// A small valid vehicle: a frame on one wheelset.
std::string vehicle_text(const std::string& body_extra = "", const std::string& element = "") {
  return R"({
  "name": "test",  // comments are allowed
  "bodies": [
    {"name": "frame", "kind": "bogie_frame", "mass": 2000, "inertia": [1000, 1000, 1500], "position": [0, 0, 0.6])" +
         body_extra + R"(},
    {"name": "ws", "kind": "wheelset", "mass": 1000, "inertia": [600, 80, 600], "position": [1, 0, 0.46]}
  ],
  "elements": [
    {"name": "primary", "kind": "spring_damper", "bodies": ["ws", "frame"], "attachments": [[0, 1, 0], [1, 1, -0.14]],
     "stiffness": [1e6, 1e6, 1e6], "damping": [0, 1e4, 1e4]})" +
         element + R"(
  ]
})";
}

std::string error_of(const std::string& text) {
  try {
    parse_vehicle(text, "v.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(VehicleFile, ASmallVehicleReadsAsWritten) {
  const VehicleDescription v = parse_vehicle(vehicle_text(), "v.json");
  EXPECT_EQ(v.name, "test");
  ASSERT_EQ(v.bodies.size(), 2u);
  ASSERT_EQ(v.wheelsets().size(), 1u);
  EXPECT_EQ(v.wheelsets()[0]->name, "ws");
  EXPECT_EQ(v.body("frame")->inertia[2], 1500.0);
  ASSERT_EQ(v.elements.size(), 1u);
  EXPECT_EQ(v.elements[0].attachments[1][2], -0.14);
  EXPECT_EQ(v.elements[0].damping[0], 0.0);
}

TEST(VehicleFile, BadFilesAreRefusedNamingFileBodyOrElementAndKey) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {vehicle_text(R"(, "colour": "red")"), "v.json: body 'frame': colour: unknown key"},
      {vehicle_text(R"(, "mass": 3)"), "v.json: mass: key given twice"},
      {R"({"name": "x", "bodies": [], "elements": []})", "v.json: the vehicle has no body of kind wheelset"},
      {R"({"name": "x", "elements": []})", "v.json: bodies: missing"},
      {vehicle_text("", R"(, {"name": "s", "kind": "spring_damper", "bodies": ["ws", "carbody"],
                       "attachments": [[0,0,0],[0,0,0]]})"),
       "v.json: element 's': bodies: 'carbody' is no body of the vehicle (bodies: frame, ws, track)"},
      {vehicle_text("", R"(, {"name": "s", "kind": "spring_damper", "bodies": ["ws", "ws"],
                       "attachments": [[0,0,0],[0,0,0]]})"),
       "v.json: element 's': bodies: joins 'ws' to itself"},
      {vehicle_text("", R"(, {"name": "s", "kind": "spring_damper", "bodies": ["ws", "track"],
                       "attachments": [[0,0,0],[0,0,0]], "stiffness": [1, -2, 3]})"),
       "v.json: element 's': stiffness: -2 is negative"},
      {vehicle_text("", R"(, {"name": "s", "kind": "bump_stop", "bodies": ["ws", "frame"], "direction": "y",
                       "attachments": [[0,0,0],[0,0,0]], "clearance": 0.01, "stiffness": 0})"),
       "v.json: element 's': stiffness: 0 [N/m] is not positive"},
      {vehicle_text("", R"(, {"name": "s", "kind": "bump_stop", "bodies": ["ws", "frame"], "direction": "w",
                       "attachments": [[0,0,0],[0,0,0]], "clearance": 0.01, "stiffness": 1e6})"),
       "v.json: element 's': direction: 'w' is none of x, y, z"},
      {vehicle_text("", R"(, {"name": "d", "kind": "nonlinear_damper", "bodies": ["ws", "frame"], "direction": "x",
                       "attachments": [[0,0,0],[0,0,0]], "curve": [[0, 0], [0.1, 5e3], [0.05, 6e3]]})"),
       "v.json: element 'd': curve: velocities must increase: point 2 has 0.050000000000000003 m/s after 0.10000000000000001"},
      {vehicle_text("", R"(, {"name": "d", "kind": "nonlinear_damper", "bodies": ["ws", "frame"], "direction": "x",
                       "attachments": [[0,0,0],[0,0,0]], "curve": [[0, 0], [0.1, 5e3], [0.2, 4e3]]})"),
       "v.json: element 'd': curve: forces must not decrease: point 2 has 4000 N after 5000"},
      {vehicle_text("", R"(, {"name": "t", "kind": "hinge", "bodies": ["ws", "frame"], "attachments": [[0,0,0],[0,0,0]]})"),
       "v.json: element 't': kind: 'hinge' is none of spring_damper, torsional_spring, bump_stop, nonlinear_damper"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string got = error_of(text);
    EXPECT_EQ(got.rfind(expected, 0), 0u) << "expected: " << expected << "\n     got: " << got;
    EXPECT_EQ(got.find('\n'), std::string::npos) << "one line: " << got;
  }
  // Negative mass and an inertia tensor that is not positive definite (a product of inertia larger
  // than the moments allow).
  std::string text = vehicle_text();
  text.replace(text.find("\"mass\": 2000"), 12, "\"mass\": -5");
  EXPECT_EQ(error_of(text).rfind("v.json: body 'frame': mass: -5 [kg] is not positive", 0), 0u) << error_of(text);
  EXPECT_EQ(error_of(vehicle_text(R"(, "products_of_inertia": [1200, 0, 0])"))
                .rfind("v.json: body 'frame': inertia: the inertia tensor", 0),
            0u)
      << error_of(vehicle_text(R"(, "products_of_inertia": [1200, 0, 0])"));
  // Positive definite, but principal moments 100, 1500, 1900 kg m^2: 1900 > 100 + 1500.
  EXPECT_NE(error_of(vehicle_text(R"(, "products_of_inertia": [900, 0, 0])")).find("break the triangle inequality"),
            std::string::npos)
      << error_of(vehicle_text(R"(, "products_of_inertia": [900, 0, 0])"));
  EXPECT_EQ(error_of(vehicle_text(R"(, "products_of_inertia": [200, 0, 0])")), "(accepted)");
}

TEST(VehicleFile, TheShippedParameterSetsReadAndHoldTheirSources) {
  // The Cooperrider car (DYTSI's values): 44388 kg body, two 2918.9 kg frames, four 1022 kg
  // wheelsets; the static wheel load (44388 + 2 x 2918.9 + 4 x 1022) kg x 9.81 / 8 = 66.6 kN.
  const VehicleDescription car = read_vehicle_file(kDir + "cooperrider-car.json");
  ASSERT_EQ(car.wheelsets().size(), 4u);
  double mass = 0;
  for (const VehicleBody& b : car.bodies) mass += b.mass;
  EXPECT_NEAR(mass, 44388 + 2 * 2918.9 + 4 * 1022, 1e-9);
  EXPECT_NEAR(mass * 9.81 / 8, 66.6e3, 0.05e3);
  // One of its bogies under a body that follows the track.
  const VehicleDescription bogie = read_vehicle_file(kDir + "cooperrider-bogie.json");
  EXPECT_EQ(bogie.wheelsets().size(), 2u);
  // Today's single wheelset: the benchmark's mass and inertias, two axle boxes on the track.
  const VehicleDescription single = read_vehicle_file(kDir + "single-wheelset.json");
  ASSERT_EQ(single.wheelsets().size(), 1u);
  EXPECT_EQ(single.bodies.size(), 1u);
  EXPECT_EQ(single.wheelsets()[0]->mass, 1813.0);
  for (const VehicleElement& e : single.elements) EXPECT_EQ(e.bodies[1], kTrackBody) << e.name;
  // The Manchester coach: the published masses (32000 kg body, two 2615 kg frames, four 1813 kg
  // wheelsets), pivots at +-9.5 m, wheelsets +-1.28 m from them, and the published vertical
  // springs and dampers (docs/vehicle.md, "The Manchester coach").
  const VehicleDescription coach = read_vehicle_file(kDir + "manchester-coach.json");
  ASSERT_EQ(coach.wheelsets().size(), 4u);
  ASSERT_EQ(coach.bodies.size(), 7u);
  mass = 0;
  for (const VehicleBody& b : coach.bodies) {
    mass += b.mass;
    if (b.kind == BodyKind::kCarBody) {
      EXPECT_EQ(b.inertia[1], 1.97e6);
    } else if (b.kind == BodyKind::kBogieFrame) {
      EXPECT_EQ(std::abs(b.position[0]), 9.5) << b.name;
      EXPECT_EQ(b.inertia[1], 1476.0) << b.name;
    }
  }
  EXPECT_NEAR(mass, 32000 + 2 * 2615 + 4 * 1813, 1e-9);
  int primary = 0, secondary = 0;
  for (const VehicleElement& e : coach.elements) {
    if (e.name.find("_primary_") != std::string::npos) {
      ++primary;
      EXPECT_EQ(e.stiffness[2], 1.2e6) << e.name;
      EXPECT_EQ(e.damping[2], 4.0e3) << e.name;
      EXPECT_EQ(std::abs(e.attachments[1][0]), 1.28) << e.name;
    }
    if (e.name.find("_secondary_") != std::string::npos) {
      ++secondary;
      EXPECT_EQ(e.stiffness[2], 4.3e5) << e.name;
      EXPECT_EQ(e.damping[2], 2.0e4) << e.name;
    }
  }
  EXPECT_EQ(primary, 8);
  EXPECT_EQ(secondary, 4);
}

}  // namespace
}  // namespace wrc
