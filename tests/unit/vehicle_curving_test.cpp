// SPDX-License-Identifier: Apache-2.0
// A vehicle's equations (core/vehicle_dynamics/) run through a curve against the linear
// steady-curving theory of a two-axle bogie (core/vehicle/bogie_steady_curving.hpp, derived in
// docs/bogie-curving.md, whose last section derives the tolerances used here).
//
// The vehicle is the shipped Cooperrider bogie (parameters/vehicles/cooperrider-bogie.json: a frame
// and two wheelsets on primary springs, its secondary springs and dampers tied to the track) on a
// cone of conicity 0.05 with r0 = 0.425 m on a 0.1 m circular rail head, gauge 1.5 m, friction 10
// ("linear creep": FASTSIM far from saturation), at 20 m/s, no cant. It enters the curve from a
// straight through a 40 m transition and runs there until it has settled. The theory takes the
// contact's linear values from wrc's own geometry and contact at the static wheel load
// (wickens_from_model(): conicity, rolling radius, contact half distance, f11, f22, f23 from the
// Hertz patch and Kalker's coefficients, the gravitational stiffness) and the uncompensated
// lateral acceleration -V^2 / R of every body.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "core/dynamics/linear_stability.hpp"
#include "core/dynamics/wickens_from_model.hpp"
#include "core/geometry/wheelset_geometry.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "core/vehicle/bogie_steady_curving.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "cone_on_circle.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.425;     // [m] the Cooperrider wheel's radius
constexpr double kSpeed = 20.0;   // [m/s]
constexpr double kFriction = 10.0;
// Bodies of the bogie file, in its order.
constexpr size_t kFrame = 0, kLeading = 1, kTrailing = 2;

std::shared_ptr<const WheelsetGeometry> cone_on_circle() {
  static const auto g = test::cone_on_circle("0.05", kR0);
  return g;
}

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  return std::make_shared<InProcessContact>(make_contact_model(model, cone_on_circle()));
}

VehicleDescription cooperrider_bogie() {
  return read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-bogie.json");
}

// A run of the bogie through a straight of 10 m and a 40 m transition into a curve of radius R
// [m] (left, or right for R < 0), to t_end [s].
VehicleRunSpec curve_run(double radius, double t_end) {
  VehicleRunSpec spec;
  spec.vehicle = cooperrider_bogie();
  spec.run.wheelset.speed = kSpeed;
  spec.run.wheelset.material.friction = kFriction;
  spec.run.wheelset.lateral_force = 0.0;
  spec.run.integrator.t_end = t_end;
  spec.run.integrator.output_period = 0.01;
  const TrackSegment straight{TrackSegmentKind::kStraight, 10.0};
  const TrackSegment transition{TrackSegmentKind::kTransition, 40.0};
  const TrackSegment curve{TrackSegmentKind::kCurve, 2000.0, std::abs(radius), radius > 0.0, 0.0};
  spec.run.track = TrackLayout({straight, transition, curve});
  return spec;
}

// The theory's bogie: the file's masses and springs (docs/bogie-curving.md, "Numbers"), the contact
// of the cone at the static wheel load [N] from the model, and the curve's 1/R and -V^2/R.
BogieCurvingResult theory(double radius, double wheel_load) {
  BogieCurvingParameters p;
  p.curvature = 1.0 / radius;
  p.lateral_acceleration = -kSpeed * kSpeed / radius;
  p.frame_mass = 2918.9;
  p.wheelset_mass = 1022.0;
  p.semi_wheelbase = 1.074;
  p.primary_longitudinal_stiffness = 3.646e6;
  p.primary_lateral_stiffness = 1.823e6;
  p.primary_semi_spacing = 0.62;
  p.secondary_lateral_stiffness = 2.0 * 1.823e5;
  p.secondary_yaw_stiffness = 2.0 * 9.0335e5 * 0.68 * 0.68;
  WheelsetParameters w;
  w.mass = p.wheelset_mass;
  w.vertical_force = 2.0 * wheel_load - w.mass * w.gravity;
  w.lateral_force = 0.0;
  w.material.friction = kFriction;
  // The primary vertical springs resist the roll that comes with a lateral shift: part of the
  // gravitational stiffness as wickens_from_model() takes it (2 k_z b1^2 (d roll/dy)^2).
  w.suspension = PrimarySuspension::none();
  w.suspension.vertical_stiffness = 3.646e6;
  w.suspension.half_spacing = 0.62;
  LinearStability linear(w, contact("onepoint"), kR0);
  const WickensFromModel m = wickens_from_model(*cone_on_circle(), w, linear.steady_state(kSpeed));
  p.conicity = m.model.conicity;
  p.rolling_radius = m.model.rolling_radius;
  p.contact_half_distance = m.model.contact_half_distance;
  p.f11 = m.model.f11;
  p.f22 = m.model.f22;
  p.f23 = w.material.shear_modulus * std::pow(m.semi_axis_a * m.semi_axis_b, 1.5) * m.c23;
  p.gravitational_lateral_stiffness = m.gravitational_stiffness;
  return bogie_steady_curving(p);
}

// (y_f, psi_f, y_1, psi_1, y_2, psi_2) of a snapshot and of the theory.
std::array<double, 6> displacements(const VehicleSnapshot& s) {
  const auto& b = s.bodies;
  return {b[kFrame].displacement[kBodyLateral], b[kFrame].displacement[kBodyYaw],
          b[kLeading].displacement[kBodyLateral], b[kLeading].displacement[kBodyYaw],
          b[kTrailing].displacement[kBodyLateral], b[kTrailing].displacement[kBodyYaw]};
}
std::array<double, 6> displacements(const BogieCurvingResult& r) {
  return {r.frame_lateral, r.frame_yaw, r.wheelsets[0].lateral, r.wheelsets[0].yaw, r.wheelsets[1].lateral,
          r.wheelsets[1].yaw};
}

// The largest difference on the theory's scales (docs/bogie-curving.md): lateral ones over the
// wheelsets' largest |y_i|, angles over a / |R|.
double scaled_difference(const std::array<double, 6>& a, const std::array<double, 6>& b, double y_scale,
                         double psi_scale) {
  double d = 0.0;
  for (size_t k = 0; k < 6; ++k) d = std::max(d, std::abs(a[k] - b[k]) / (k % 2 == 0 ? y_scale : psi_scale));
  return d;
}

struct CurveOutcome {
  std::array<double, 6> run_end, steady, linear;
  double y_scale = 0, psi_scale = 0;
  VehicleSnapshot first_sample, last_sample;
  BogieCurvingResult theory;
  double wheel_load = 0;  // [N] static
  BodyAccelerationMaxima frame_maxima, wheelset_maxima;
};

CurveOutcome run_curve(double radius, const std::string& model) {
  VehicleSimulation run(curve_run(radius, 12.0), contact(model), kR0);
  CurveOutcome o;
  run.on_output([&o](const VehicleSnapshot& s) {
    if (s.t == 0.0) o.first_sample = s;
    o.last_sample = s;
  });
  run.run();
  EXPECT_EQ(run.state(), RunState::kFinished) << run.message();
  o.run_end = displacements(run.snapshot());
  o.steady = displacements(run.steady_state(run.time()));
  o.wheel_load = run.wheel_loads()[0];
  o.frame_maxima = run.acceleration_maxima(kFrame);
  o.wheelset_maxima = run.acceleration_maxima(kLeading);
  o.theory = theory(radius, o.wheel_load);
  o.linear = displacements(o.theory);
  o.y_scale = std::max(std::abs(o.linear[2]), std::abs(o.linear[4]));
  o.psi_scale = 1.074 / std::abs(radius);
  return o;
}

// docs/bogie-curving.md, "The tolerance of a nonlinear simulation against this theory": on the cone
// with spin and the gravitational stiffness in the theory, the neglected second-order kinematics,
// contact angle, FASTSIM's coefficients and the start of saturation sum to 1.2 % at R = 3000 m and
// 3.4 % at R = 600 m; asserted: 2 % and 5 %. Measured: 1.16 % at both radii (the angles of attack),
// so what differs is linear in 1/R (creep coefficients, contact angle), not the kinematics. The run ends within 1e-3 of the scales of the steady
// state it settles on (the lightly damped frame's last oscillation, decaying). A gross error is far
// outside: a lost factor 2 in a creep coefficient moves the results by tens of percent, a wrong
// sign of the curve's terms by 200 %.
TEST(VehicleCurving, TheCooperriderBogieOnTheConeCurvesAsTheLinearTheoryHasIt) {
  for (const auto& [radius, tolerance] : {std::pair{3000.0, 0.02}, std::pair{600.0, 0.05}}) {
    SCOPED_TRACE("R = " + std::to_string(radius) + " m");
    const CurveOutcome o = run_curve(radius, "onepoint");
    EXPECT_LT(scaled_difference(o.run_end, o.steady, o.y_scale, o.psi_scale), 1e-3);
    EXPECT_LT(scaled_difference(o.steady, o.linear, o.y_scale, o.psi_scale), tolerance);
    // The shape the theory predicts: both wheelsets outwards (y < 0 in a left curve), the leading
    // one further, pointing outwards (psi_1 < 0), the trailing one inwards.
    EXPECT_LT(o.steady[2], o.steady[4]);
    EXPECT_LT(o.steady[4], 0.0);
    EXPECT_LT(o.steady[3], 0.0);
    EXPECT_GT(o.steady[5], 0.0);
  }
}

// The elastic formulation (multipoint: normal forces from Hertz springs) curves alike: it differs
// from the rigid one by the wheels' vertical compliance only.
TEST(VehicleCurving, TheElasticFormulationCurvesAsTheRigidOne) {
  const CurveOutcome rigid = run_curve(3000.0, "onepoint");
  const CurveOutcome elastic = run_curve(3000.0, "multipoint");
  EXPECT_LT(scaled_difference(elastic.steady, elastic.linear, elastic.y_scale, elastic.psi_scale), 0.02);
  EXPECT_LT(scaled_difference(elastic.steady, rigid.steady, rigid.y_scale, rigid.psi_scale), 2e-3);
}

// Mirror symmetry: a right curve gives the left curve's lateral displacements and yaw angles
// negated (the cone and the bogie are symmetric); rounding only, 1e-9 of the scales.
TEST(VehicleCurving, ARightCurveMirrorsALeftOne) {
  const CurveOutcome left = run_curve(3000.0, "onepoint");
  const CurveOutcome right = run_curve(-3000.0, "onepoint");
  std::array<double, 6> mirrored{};
  for (size_t k = 0; k < 6; ++k) mirrored[k] = -right.steady[k];
  EXPECT_LT(scaled_difference(mirrored, left.steady, left.y_scale, left.psi_scale), 1e-9);
}

// The wheels' forces, which a run reports per wheelset (VehicleSnapshot::wheels, as the lone
// wheelset's run: docs/run-quantities.md), balance what the bodies carry:
//  - at rest on the straight (t = 0): the four wheels' Q sum to the bogie's weight and the car
//    body's share, (2918.9 + 2 x 1022) kg x 9.81 m/s^2 + 217723.1 N, less what the secondary
//    springs hold (2 x 333300 N/m times the frame's height above their track points, 17.074 mm
//    below its nominal: 0.3 mm on the cone), to 1e-7 of it (the rest state's Newton tolerance);
//    each wheel pushes its rail outwards (Y = 555 N: the normal force's lateral part on the cone's
//    slope less the spin creep force), and the two of a wheelset alike, sum Y = 0 to 1e-6 of Q;
//  - in the settled curve, each wheelset's track-shift force sum Y is what the rails must give it:
//    minus the theory's lateral creep and gravitational forces (its lateral balance with its
//    springs and m a_y); within 3 % of the larger, the displacements' tolerance (the forces follow
//    from the angles of attack and offsets the tolerance holds);
//  - the frame's absolute lateral acceleration is the curve's centripetal V^2 / R (to 1e-3: its
//    offset y_f changes the radius by 2 mm of 3000 m), its vertical 0; the run's maxima of them
//    (the summary's) are at least that, in the curve.
TEST(VehicleCurving, TheWheelsForcesBalanceTheBogie) {
  const double radius = 3000.0;
  const CurveOutcome o = run_curve(radius, "onepoint");
  ASSERT_EQ(o.first_sample.wheels.size(), 2u);
  double q = 0.0;
  for (const auto& wheels : o.first_sample.wheels) {
    for (const WheelOutput& w : wheels) q += w.vertical_force;
    EXPECT_GT(wheels[0].lateral_force, 0.0);
    EXPECT_LT(std::abs(track_shift_force(wheels[0].lateral_force, wheels[1].lateral_force)),
              1e-6 * wheels[0].vertical_force);
  }
  const double weight = (2918.9 + 2.0 * 1022.0) * 9.81 + 217723.1;
  const double secondary = 2.0 * 333300.0 * (-0.017074 - o.first_sample.bodies[kFrame].displacement[kBodyVertical]);
  EXPECT_NEAR(q, weight - secondary, 1e-7 * weight);
  EXPECT_NEAR(o.wheel_load, weight / 4.0, 1e-9 * weight);
  double largest = 0.0;
  std::array<double, 2> expected{};
  for (size_t i = 0; i < 2; ++i) {
    const WheelsetCurvingState& w = o.theory.wheelsets[i];
    expected[i] = -(w.lateral_creep_force + w.gravitational_force);
    largest = std::max(largest, std::abs(expected[i]));
  }
  for (size_t i = 0; i < 2; ++i) {
    const auto& wheels = o.last_sample.wheels[i];
    EXPECT_NEAR(track_shift_force(wheels[0].lateral_force, wheels[1].lateral_force), expected[i], 0.03 * largest)
        << "wheelset " << i + 1;
  }
  const std::array<double, 2>& frame = o.last_sample.accelerations[kFrame];
  EXPECT_NEAR(frame[0], kSpeed * kSpeed / radius, 1e-3 * kSpeed * kSpeed / radius);
  EXPECT_NEAR(frame[1], 0.0, 1e-4);
  // The run's largest lateral acceleration of the frame (its summary's): at least the settled
  // V^2 / R, reached in the curve (the transition ends at 50 m; the frame at x = 0 of the bogie);
  // its vertical one stays small; a wheelset's are not kept.
  const RunMaximum& lateral = o.frame_maxima.lateral;
  EXPECT_GE(lateral.value, (1.0 - 1e-3) * kSpeed * kSpeed / radius);
  EXPECT_LE(lateral.value, 1.2 * kSpeed * kSpeed / radius);
  EXPECT_GE(lateral.distance, 50.0);
  EXPECT_NEAR(lateral.distance, kSpeed * lateral.t, 1e-9);
  EXPECT_LT(o.frame_maxima.vertical.value, 1e-3);
  EXPECT_EQ(o.wheelset_maxima.lateral.value, 0.0);
}

}  // namespace
}  // namespace wrc
