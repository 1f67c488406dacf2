// SPDX-License-Identifier: Apache-2.0
// A vehicle's equations (core/vehicle_dynamics/) against the linear steady-curving theory of a
// two-axle bogie (core/vehicle/bogie_steady_curving.hpp, docs/bogie-curving.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/wickens_from_model.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/vehicle/bogie_steady_curving.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.425;

std::shared_ptr<const WheelsetGeometry> cone_on_circle() {
  TrackParameters t;
  t.gauge = 1.5;
  t.gauge_depth = 0.0;
  t.inclination = 0.0;
  t.nominal_radius = kR0;
  static const auto g = std::make_shared<const WheelsetGeometry>(make_profile("conic:0.05", ProfileSide::kWheel),
                                                                 make_profile("circle:0.1", ProfileSide::kRail), t);
  return g;
}

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  return std::make_shared<InProcessContact>(make_contact_model(model, cone_on_circle()));
}

TEST(VehicleCurving, Explore) {
  const double radius = 3000.0, speed = 20.0;
  VehicleRunSpec spec;
  spec.vehicle = read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-bogie.json");
  spec.run.wheelset.speed = speed;
  spec.run.wheelset.material.friction = 10.0;
  spec.run.wheelset.lateral_force = 0.0;
  spec.run.integrator.t_end = 6.0;
  spec.run.integrator.output_period = 0.5;
  TrackSegment straight{TrackSegmentKind::kStraight, 10.0};
  TrackSegment transition{TrackSegmentKind::kTransition, 40.0};
  TrackSegment curve{TrackSegmentKind::kCurve, 1000.0, radius, true, 0.0};
  spec.run.track = TrackLayout({straight, transition, curve});
  VehicleSimulation sim(spec, contact("onepoint"), kR0);
  sim.on_output([](const VehicleSnapshot& s) {
    std::printf("t=%.2f  frame y=%.4e yaw=%.4e z=%.4e | ws1 y=%.4e yaw=%.4e z=%.4e | ws2 y=%.4e yaw=%.4e\n", s.t,
                s.bodies[0].displacement[0], s.bodies[0].displacement[3], s.bodies[0].displacement[1],
                s.bodies[1].displacement[0], s.bodies[1].displacement[3], s.bodies[1].displacement[1],
                s.bodies[2].displacement[0], s.bodies[2].displacement[3]);
  });
  sim.run();
  EXPECT_EQ(sim.state(), RunState::kFinished) << sim.message();
  const RunCounters c = sim.counters();
  std::printf("steps %ld queries %ld configs %ld jac %ld\n", c.steps, c.contact_queries, c.contact_configurations,
              c.jacobian_evals);

  BogieCurvingParameters p;
  p.curvature = 1.0 / radius;
  p.lateral_acceleration = -speed * speed / radius;
  p.frame_mass = 2918.9;
  p.wheelset_mass = 1022.0;
  p.semi_wheelbase = 1.074;
  p.primary_longitudinal_stiffness = 3.646e6;
  p.primary_lateral_stiffness = 1.823e6;
  p.primary_semi_spacing = 0.62;
  p.secondary_lateral_stiffness = 2.0 * 1.823e5;
  p.secondary_yaw_stiffness = 2.0 * 9.0335e5 * 0.68 * 0.68;
  WheelsetParameters wp;
  wp.mass = 1022.0;
  wp.vertical_force = 2.0 * sim.wheel_loads()[0] - 1022.0 * 9.81;
  wp.lateral_force = 0.0;
  wp.material.friction = 10.0;
  wp.suspension = PrimarySuspension::none();
  LinearStability ls(wp, contact("onepoint"), kR0);
  const WickensFromModel w = wickens_from_model(*cone_on_circle(), wp, ls.steady_state(speed));
  p.conicity = w.model.conicity;
  p.rolling_radius = w.model.rolling_radius;
  p.contact_half_distance = w.model.contact_half_distance;
  p.f11 = w.model.f11;
  p.f22 = w.model.f22;
  p.gravitational_lateral_stiffness = w.gravitational_stiffness;
  p.f23 = wp.material.shear_modulus * std::pow(w.semi_axis_a * w.semi_axis_b, 1.5) * w.c23;
  const BogieCurvingResult r = bogie_steady_curving(p);
  std::printf("theory frame y=%.4e yaw=%.4e | ws1 y=%.4e yaw=%.4e | ws2 y=%.4e yaw=%.4e\n", r.frame_lateral,
              r.frame_yaw, r.wheelsets[0].lateral, r.wheelsets[0].yaw, r.wheelsets[1].lateral, r.wheelsets[1].yaw);
}

}  // namespace
}  // namespace wrc
