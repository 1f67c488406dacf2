// SPDX-License-Identifier: Apache-2.0
// The vehicle of a run command (protocol/run/vehicle_codec.hpp): the shipped Cooperrider car (every
// body, element and damper-curve point; every kind of element) through run_command_t and its LCM
// encoding exactly, no vehicle as no bodies, and each bad field named.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bus/transport/decode.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "protocol/run/vehicle_codec.hpp"

namespace wrc::protocol {
namespace {

RunRequest request_with(const std::optional<VehicleDescription>& vehicle) {
  RunRequest r;
  r.model = "spline";
  r.run_id = "car";
  r.vehicle = vehicle;
  return r;
}

std::string error_of(const run_command_t& command) {
  try {
    from_message(command);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

// The car with one element of each of the other kinds added (a bump stop, a yaw damper with
// blow-off), so that every field crosses.
VehicleDescription car_with_every_kind() {
  VehicleDescription v = read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-car.json");
  VehicleElement stop;
  stop.name = "front_lateral_stop";
  stop.kind = ElementKind::kBumpStop;
  stop.bodies = {"front_frame", "car_body"};
  stop.attachments = {{{0, 0, 0.2}, {7.5, 0, -1.3}}};
  stop.direction = 1;
  stop.clearance = 0.03;
  stop.stop_stiffness = 2.5e6;
  v.elements.push_back(stop);
  VehicleElement damper;
  damper.name = "rear_yaw_damper_blow_off";
  damper.kind = ElementKind::kNonlinearDamper;
  damper.bodies = {"rear_frame", "car_body"};
  damper.attachments = {{{0, 1.4, 0.15}, {-7.5, 1.4, -1.4}}};
  damper.direction = 0;
  damper.curve = {{0.0, 0.0}, {0.02, 8000.0}, {0.1, 9500.5}};
  v.elements.push_back(damper);
  return v;
}

TEST(VehicleCodec, TheCarCrossesExactly) {
  const VehicleDescription car = car_with_every_kind();
  const run_command_t m = to_message(request_with(car));
  std::vector<unsigned char> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  ASSERT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  run_command_t decoded;
  ASSERT_FALSE(bus::decode_bytes(bytes.data(), bytes.size(), decoded));
  const std::optional<VehicleDescription> back = from_message(decoded).vehicle;
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->name, car.name);
  ASSERT_EQ(back->bodies.size(), car.bodies.size());
  for (size_t b = 0; b < car.bodies.size(); ++b) {
    const VehicleBody &x = back->bodies[b], &y = car.bodies[b];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.mass, y.mass);
    EXPECT_EQ(x.inertia, y.inertia);
    EXPECT_EQ(x.products_of_inertia, y.products_of_inertia);
    EXPECT_EQ(x.position, y.position);
    EXPECT_EQ(x.external_force, y.external_force);
  }
  ASSERT_EQ(back->elements.size(), car.elements.size());
  for (size_t e = 0; e < car.elements.size(); ++e) {
    const VehicleElement &x = back->elements[e], &y = car.elements[e];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.bodies, y.bodies);
    EXPECT_EQ(x.attachments, y.attachments);
    EXPECT_EQ(x.stiffness, y.stiffness);
    EXPECT_EQ(x.damping, y.damping);
    EXPECT_EQ(x.yaw_stiffness, y.yaw_stiffness);
    EXPECT_EQ(x.roll_stiffness, y.roll_stiffness);
    EXPECT_EQ(x.yaw_damping, y.yaw_damping);
    EXPECT_EQ(x.roll_damping, y.roll_damping);
    EXPECT_EQ(x.direction, y.direction);
    EXPECT_EQ(x.clearance, y.clearance);
    EXPECT_EQ(x.stop_stiffness, y.stop_stiffness);
    EXPECT_EQ(x.curve, y.curve);
  }
  // No vehicle: no bodies, and none back.
  const run_command_t none = to_message(request_with(std::nullopt));
  EXPECT_EQ(none.num_vehicle_bodies, 0);
  EXPECT_FALSE(from_message(none).vehicle.has_value());
}

TEST(VehicleCodec, EachBadFieldIsNamed) {
  const run_command_t m = to_message(request_with(car_with_every_kind()));
  run_command_t count = m;
  count.num_vehicle_bodies = 6;
  EXPECT_EQ(error_of(count), "num_vehicle_bodies = 6 does not match the 7 entries of its list");
  run_command_t kind = m;
  kind.vehicle_bodies[2].kind = 9;
  EXPECT_EQ(error_of(kind), "vehicle: body 'front_wheelset_1': kind: 9 is none of CAR_BODY, BOGIE_FRAME, WHEELSET");
  run_command_t direction = m;
  direction.vehicle_elements.back().direction = 3;
  EXPECT_EQ(error_of(direction), "vehicle: element 'rear_yaw_damper_blow_off': direction: 3 is none of 0 (x), 1 (y), 2 (z)");
  run_command_t body = m;
  body.vehicle_elements[0].body_b = "frame";
  EXPECT_NE(error_of(body).find("vehicle: element 'front_wheelset_1_primary_left': bodies: 'frame' is no body"),
            std::string::npos)
      << error_of(body);
  run_command_t mass = m;
  mass.vehicle_bodies[0].mass = -1.0;
  EXPECT_NE(error_of(mass).find("vehicle: body 'car_body': mass"), std::string::npos) << error_of(mass);
  run_command_t curve = m;
  curve.vehicle_elements.back().curve_force.pop_back();
  EXPECT_EQ(error_of(curve), "vehicle: element 'rear_yaw_damper_blow_off': curve: 2 forces for 3 velocities");
  run_command_t orphans = to_message(request_with(std::nullopt));
  orphans.vehicle_elements.push_back(m.vehicle_elements[0]);
  orphans.num_vehicle_elements = 1;
  EXPECT_EQ(error_of(orphans), "vehicle: elements without bodies");
}

}  // namespace
}  // namespace wrc::protocol
