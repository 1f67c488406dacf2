// SPDX-License-Identifier: Apache-2.0
// A vehicle file of one wheelset on the track as the wheelset run's parameters
// (apply_single_wheelset): the shipped single-wheelset file gives every wheelset parameter of the
// benchmark exactly (so a run from it is the benchmark's, bit for bit: the bus test
// VehicleRunTest checks the whole summary), a wheelset without elements is free, and what the
// wheelset equations cannot take is refused naming the vehicle, the body or element and the key.
#include "core/dynamics/single_wheelset_vehicle.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "core/dynamics/run_parameter_table.hpp"
#include "core/vehicle/vehicle_file.hpp"

namespace wrc {
namespace {

const std::string kDir = std::string(WRC_PARAMETERS_DIR) + "/vehicles/";

TEST(SingleWheelsetVehicle, TheShippedFileIsTheBenchmarksWheelsetExactly) {
  WheelsetParameters from_file;
  from_file.mass = 1.0;  // everything the file sets is overwritten
  from_file.lateral_force = 0.0;
  from_file.suspension = PrimarySuspension::none();
  apply_single_wheelset(read_vehicle_file(kDir + "single-wheelset.json"), from_file);
  const WheelsetParameters benchmark;  // the defaults are parameters/benchmark.json's
  for (const Parameter<WheelsetParameters>& p : wheelset_parameter_table())
    EXPECT_EQ(p.get(from_file), p.get(benchmark)) << p.key;
  const PrimarySuspension& s = from_file.suspension;
  const PrimarySuspension b = PrimarySuspension::benchmark();
  EXPECT_EQ(s.longitudinal_stiffness, b.longitudinal_stiffness);
  EXPECT_EQ(s.lateral_stiffness, b.lateral_stiffness);
  EXPECT_EQ(s.vertical_stiffness, b.vertical_stiffness);
  EXPECT_EQ(s.longitudinal_damping, b.longitudinal_damping);
  EXPECT_EQ(s.lateral_damping, b.lateral_damping);
  EXPECT_EQ(s.vertical_damping, b.vertical_damping);
  EXPECT_EQ(s.half_spacing, b.half_spacing);
}

const char* kLoneWheelset = R"({
  "name": "lone",
  "bodies": [{"name": "ws", "kind": "wheelset", "mass": 1500, "inertia": [800, 90, 800], "position": [0, 0, 0.45],
              "external_force": [0, 1000, -1e5]}],
  "elements": [
    {"name": "left", "kind": "spring_damper", "bodies": ["ws", "track"], "attachments": [[0, 0.9, 0], [0, 0.9, 0.45]],
     "stiffness": [1e7, 2e5, 5e5], "damping": [0, 1e4, 3e3]},
    {"name": "right", "kind": "spring_damper", "bodies": ["track", "ws"], "attachments": [[0, -0.9, 0.45], [0, -0.9, 0]],
     "stiffness": [1e7, 2e5, 5e5], "damping": [0, 1e4, 3e3]}
  ]
})";

// The keys land where the wheelset equations read them: inertia [xx, yy, zz] as roll, spin, yaw;
// the external force's y as the lateral load, minus its z as the downward load; the axle boxes at
// +-0.9 m (either body order) as the suspension; without elements the wheelset is free.
TEST(SingleWheelsetVehicle, EachKeyLandsWhereTheEquationsReadIt) {
  WheelsetParameters p;
  apply_single_wheelset(parse_vehicle(kLoneWheelset, "lone.json"), p);
  EXPECT_EQ(p.mass, 1500.0);
  EXPECT_EQ(p.roll_inertia, 800.0);
  EXPECT_EQ(p.spin_inertia, 90.0);
  EXPECT_EQ(p.yaw_inertia, 800.0);
  EXPECT_EQ(p.lateral_force, 1000.0);
  EXPECT_EQ(p.vertical_force, 1e5);
  EXPECT_EQ(p.suspension.half_spacing, 0.9);
  EXPECT_EQ(p.suspension.lateral_stiffness, 2e5);
  EXPECT_EQ(p.suspension.vertical_damping, 3e3);
  std::string free_text = kLoneWheelset;
  free_text = free_text.substr(0, free_text.find("\"elements\"")) + "\"elements\": []}";
  apply_single_wheelset(parse_vehicle(free_text, "free.json"), p);
  EXPECT_EQ(p.suspension.longitudinal_stiffness, 0.0);
  EXPECT_EQ(p.suspension.lateral_damping, 0.0);
}

std::string error_of(const std::string& text) {
  WheelsetParameters p;
  try {
    apply_single_wheelset(parse_vehicle(text, "v.json"), p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(SingleWheelsetVehicle, WhatTheWheelsetEquationsCannotTakeIsRefusedNamingIt) {
  WheelsetParameters p;
  try {
    apply_single_wheelset(read_vehicle_file(kDir + "cooperrider-car.json"), p);
    ADD_FAILURE() << "the Cooperrider car was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bodies: 7; the lone wheelset's equations take one wheelset"), std::string::npos) << e.what();
  }
  const std::string base = kLoneWheelset;
  const struct {
    std::string text, expected;
  } cases[] = {
      {replaced(base, "\"position\": [0, 0, 0.45],", "\"position\": [0, 0, 0.45], \"products_of_inertia\": [0, 5, 0],"),
       "vehicle 'lone': body 'ws': products_of_inertia: [0, 5, 0] [kg m^2]"},
      {replaced(replaced(replaced(base, "[0, 0.9, 0.45]", "[0.2, 0.9, 0.45]"), "[0, -0.9, 0.45]", "[0.2, -0.9, 0.45]"),
                "\"position\": [0, 0, 0.45]", "\"position\": [0.2, 0, 0.45]"),
       "body 'ws': position: [0.2, 0, 0.45] [m]"},
      {replaced(base, "[0, 1000, -1e5]", "[50, 1000, -1e5]"), "body 'ws': external_force: [50, 1000, -100000] [N]"},
      {replaced(base, "[0, 0.9, 0.45]]", "[0, 0.9, 0.5]]"),
       "element 'left': attachments: [0, 0.9, 0.5] [m] on the track: the spring is not unstretched"},
      {replaced(base, "[[0, 0.9, 0],", "[[0, 0.9, 0.1],"), "element 'left': attachments: [0, 0.9, 0.1] [m] on the wheelset"},
      {replaced(base, "[0, -0.9, 0.45], [0, -0.9, 0]]", "[0, -0.8, 0.45], [0, -0.8, 0]]"),
       "element 'right': attachments: not the mirror image of 'left'"},
      {replaced(base, "\"stiffness\": [1e7, 2e5, 5e5], \"damping\": [0, 1e4, 3e3]}\n  ]",
                "\"stiffness\": [1e7, 3e5, 5e5], \"damping\": [0, 1e4, 3e3]}\n  ]"),
       "element 'right': stiffness, damping: not those of 'left'"},
      {replaced(base, R"({"name": "left", "kind": "spring_damper", "bodies": ["ws", "track"], "attachments": [[0, 0.9, 0], [0, 0.9, 0.45]],
     "stiffness": [1e7, 2e5, 5e5], "damping": [0, 1e4, 3e3]},)",
                R"({"name": "left", "kind": "torsional_spring", "bodies": ["ws", "track"],
     "attachments": [[0, 0, 0], [0, 0, 0.45]], "yaw_stiffness": 1e6},)"),
       "element 'left': kind: torsional_spring"},
  };
  for (const auto& c : cases) EXPECT_NE(error_of(c.text).find(c.expected), std::string::npos) << error_of(c.text);
}

}  // namespace
}  // namespace wrc
