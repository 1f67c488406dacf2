// SPDX-License-Identifier: Apache-2.0
// The forces of a vehicle's elements (core/vehicle/element_forces.hpp) and the track frames they
// are computed in (core/vehicle/track_frames.hpp), against physics rather than the code: the track
// frames on a circle, a straight and a clothoid against their closed forms; the versine of a
// curve where a lateral spring between a car body and a bogie is unstretched; action and reaction
// between the bodies of the Cooperrider car in a transition; the springs' generalised forces as
// minus the gradient of a potential the test computes with its own kinematics; nothing changes
// along a constant curve, while dampers work in a transition at speed (first-order kinematics
// worked out here); mirror symmetry on straight track; the rates as time derivatives; a torsional
// spring's angles with the track's turn and cant; the laws of the bump stop and the nonlinear
// damper.
//
// The vehicle is the Cooperrider car (parameters/vehicles/cooperrider-car.json, docs/vehicle.md),
// with, for the laws it lacks, an anti-yaw torsional spring, a lateral bump stop and a pair of
// nonlinear longitudinal dampers added between the car body and its bogie frames; "anchored" adds
// elements to the track.
#include "core/vehicle/element_forces.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vehicle/track_frames.hpp"
#include "core/vehicle/vehicle_file.hpp"

namespace wrc {
namespace {

const std::string kCarFile = std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-car.json";
const std::string kBogieFile = std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-bogie.json";

// Straight 50 m, a 100 m transition (curvature and cant linear), a 600 m curve to the left with
// 0.15 m cant (the right rail raised: cant angle -asin(0.1)), 1000 m long.
TrackLayout transition_layout(double cant = 0.15) {
  return TrackLayout({{TrackSegmentKind::kStraight, 50.0, 0, true, 0},
                      {TrackSegmentKind::kTransition, 100.0, 0, true, 0},
                      {TrackSegmentKind::kCurve, 1000.0, 600.0, true, cant}});
}

VehicleElement element(const std::string& name, ElementKind kind, const std::string& a, const std::string& b,
                       std::array<double, 3> pa, std::array<double, 3> pb) {
  VehicleElement e;
  e.name = name;
  e.kind = kind;
  e.bodies = {a, b};
  e.attachments = {pa, pb};
  return e;
}

// The Cooperrider car with, between its bodies, an anti-yaw (and roll) torsional spring with
// dampers on the front bogie, a lateral bump stop on the rear one (5 mm clearance) and a
// nonlinear longitudinal damper on each side of the front one.
VehicleDescription linked_car() {
  VehicleDescription car = read_vehicle_file(kCarFile);
  VehicleElement t = element("anti_yaw", ElementKind::kTorsionalSpring, "car_body", "front_frame", {7.5, 0, -1.4},
                             {0, 0, 0.16});
  t.yaw_stiffness = 2e6;
  t.roll_stiffness = 1e6;
  t.yaw_damping = 1e4;
  t.roll_damping = 5e3;
  car.elements.push_back(t);
  VehicleElement stop = element("rear_stop", ElementKind::kBumpStop, "rear_frame", "car_body", {0, 0, 0.2},
                                {-7.5, 0, -1.2});
  stop.direction = 1;
  stop.clearance = 0.005;
  stop.stop_stiffness = 5e6;
  car.elements.push_back(stop);
  for (double side : {1.0, -1.0}) {
    VehicleElement d = element(side > 0 ? "front_damper_left" : "front_damper_right", ElementKind::kNonlinearDamper,
                               "front_frame", "car_body", {0, 1.2 * side, 0.16}, {7.5, 1.2 * side, -1.4});
    d.direction = 0;
    d.curve = {{0, 0}, {0.05, 8000}, {0.2, 12000}};
    car.elements.push_back(d);
  }
  return car;
}

// linked_car() with elements to the track besides: a spring to a track point 0.8 m ahead of the
// front wheelset (x != 0 exercises the track point's own distance) and a torsional spring tying
// the rear frame's roll and yaw to the track.
VehicleDescription anchored_car() {
  VehicleDescription car = linked_car();
  VehicleElement s = element("front_tie", ElementKind::kSpringDamper, "front_wheelset_1", kTrackBody, {0, 0.5, 0},
                             {0.8, 0.6, 0.3});
  s.stiffness = {2e5, 3e5, 4e5};
  s.damping = {1e3, 2e3, 3e3};
  car.elements.push_back(s);
  VehicleElement t = element("rear_tie", ElementKind::kTorsionalSpring, kTrackBody, "rear_frame", {0, 0, 0}, {0, 0, 0});
  t.yaw_stiffness = 3e5;
  t.roll_stiffness = 4e5;
  car.elements.push_back(t);
  return car;
}

// Every damping of the vehicle set to 0 and its nonlinear dampers removed: springs only.
VehicleDescription springs_only(VehicleDescription v) {
  std::vector<VehicleElement> kept;
  for (VehicleElement e : v.elements) {
    if (e.kind == ElementKind::kNonlinearDamper) continue;
    e.damping = {0, 0, 0};
    e.yaw_damping = e.roll_damping = 0;
    kept.push_back(e);
  }
  v.elements = kept;
  return v;
}

// Displacements up to 20 mm and 20 mrad, rates up to 0.1 m/s and 0.1 rad/s.
std::vector<BodyState> random_states(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<BodyState> states(n);
  for (BodyState& s : states)
    for (std::size_t j = 0; j < kBodyCoordinates; ++j) {
      s.displacement[j] = 0.02 * u(random);
      s.rate[j] = 0.1 * u(random);
    }
  return states;
}

std::size_t index_of(const VehicleDescription& v, const std::string& name) {
  for (std::size_t i = 0; i < v.bodies.size(); ++i)
    if (v.bodies[i].name == name) return i;
  throw std::invalid_argument("no body " + name);
}

// The test's own kinematics: a body's orientation from Eigen's angle-axis rotations (yaw about z,
// then pitch about the turned y, then roll about the twice turned x).
Eigen::Matrix3d orientation(const BodyState& s) {
  return (Eigen::AngleAxisd(s.displacement[kBodyYaw], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(s.displacement[kBodyPitch], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(s.displacement[kBodyRoll], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// A point of one end of an element and that end's orientation, in the track frame at s_ref.
struct Placed {
  Eigen::Vector3d point;
  Eigen::Matrix3d rotation;
  double distance;  // nominal distance of the point along the track [m]
};

Placed place_end(const VehicleDescription& v, const TrackLayout& layout, double s_ref,
                 const std::vector<BodyState>& q, const VehicleElement& e, int k) {
  const std::string& name = e.bodies[static_cast<std::size_t>(k)];
  const std::array<double, 3>& a = e.attachments[static_cast<std::size_t>(k)];
  const Eigen::Vector3d p(a[0], a[1], a[2]);
  Placed r;
  if (name == kTrackBody) {  // in the track frame at the other body's distance
    const VehicleBody& other = *v.body(e.bodies[static_cast<std::size_t>(1 - k)]);
    const double s = s_ref + other.position[0];
    const FramePose frame = track_frame_pose(layout, s_ref, s);
    r.point = frame.point(p);
    r.rotation = frame.rotation;
    r.distance = s + a[0];
    return r;
  }
  const std::size_t i = index_of(v, name);
  const VehicleBody& b = v.bodies[i];
  const double s = s_ref + b.position[0];
  const FramePose frame = track_frame_pose(layout, s_ref, s);
  const Eigen::Vector3d c(0, b.position[1] + q[i].displacement[kBodyLateral],
                          b.position[2] + q[i].displacement[kBodyVertical]);
  const Eigen::Matrix3d rot = orientation(q[i]);
  r.point = frame.point(c + rot * p);
  r.rotation = frame.rotation * rot;
  r.distance = s + a[0];
  return r;
}

// The elastic energy [J] of the vehicle's springs, torsional springs and bump stops, each
// deflection taken in the track frame at the element's station.
double potential(const VehicleDescription& v, const TrackLayout& layout, double s_ref,
                 const std::vector<BodyState>& q) {
  double energy = 0;
  for (const VehicleElement& e : v.elements) {
    const Placed a = place_end(v, layout, s_ref, q, e, 0);
    const Placed b = place_end(v, layout, s_ref, q, e, 1);
    const FramePose station = track_frame_pose(layout, s_ref, 0.5 * (a.distance + b.distance));
    const Eigen::Vector3d d = station.rotation.transpose() * (b.point - a.point);
    switch (e.kind) {
      case ElementKind::kSpringDamper:
        for (int j = 0; j < 3; ++j) energy += 0.5 * e.stiffness[static_cast<std::size_t>(j)] * d[j] * d[j];
        break;
      case ElementKind::kBumpStop: {
        const double beyond = std::max(0.0, std::abs(d[e.direction]) - e.clearance);
        energy += 0.5 * e.stop_stiffness * beyond * beyond;
        break;
      }
      case ElementKind::kTorsionalSpring: {
        const Eigen::Matrix3d rel = a.rotation.transpose() * b.rotation;
        const double roll = std::atan2(rel(2, 1), rel(2, 2));
        const double yaw = std::atan2(rel(1, 0), rel(0, 0));
        energy += 0.5 * e.roll_stiffness * roll * roll + 0.5 * e.yaw_stiffness * yaw * yaw;
        break;
      }
      case ElementKind::kNonlinearDamper: break;
    }
  }
  return energy;
}

double norm_of(const std::array<double, kBodyCoordinates>& q) {
  double n = 0;
  for (double x : q) n = std::max(n, std::abs(x));
  return n;
}

// ---------------------------------------------------------------------------------------------
// Track frames

TEST(VehicleElementForces, TrackFramesOnACircleAreItsChordsAndTurns) {
  // A circle of radius R to the left: the frame at s seen from the frame at s0 is turned by
  // (s - s0) / R and its origin lies at (R sin, R (1 - cos)) of that angle: exact geometry, to
  // 1e-12 m (the quadrature's error is below 1e-20 m, rounding of sums of 20 m about 1e-14 m).
  const double radius = 600.0;
  const TrackLayout left({{TrackSegmentKind::kCurve, 2000.0, radius, true, 0.0}});
  const TrackLayout right({{TrackSegmentKind::kCurve, 2000.0, radius, false, 0.0}});
  for (double s0 : {0.0, 137.25}) {
    for (double ds : {-20.0, -9.5, 0.3, 9.5, 20.0, 173.0}) {
      const double angle = ds / radius;
      for (double sign : {1.0, -1.0}) {
        const FramePose p = track_frame_pose(sign > 0 ? left : right, s0, s0 + ds);
        const double scale = std::max(1.0, std::abs(ds) / 20.0);  // the longest span sums 9 parts
        EXPECT_NEAR(p.translation.x(), radius * std::sin(angle), 1e-12 * scale) << ds;
        EXPECT_NEAR(p.translation.y(), sign * radius * (1.0 - std::cos(angle)), 1e-12 * scale) << ds;
        EXPECT_EQ(p.translation.z(), 0.0);
        EXPECT_NEAR(std::atan2(p.rotation(1, 0), p.rotation(0, 0)), sign * angle, 1e-15);
        EXPECT_NEAR(track_heading_change(sign > 0 ? left : right, s0, s0 + ds), sign * angle, 1e-15);
      }
    }
  }
  // With cant (cant angle phi = -asin(0.15 / 1.5) in a left curve) the frames are rolled: the
  // frame at s0 sees the next frame's origin, level with it but towards the curve's centre, above
  // its tilted x-y plane by -y sin(phi), and that frame's axes as Rx(-phi) Rz(angle) Rx(phi).
  const TrackLayout canted({{TrackSegmentKind::kCurve, 2000.0, radius, true, 0.15}});
  const double phi = -std::asin(0.1);
  const FramePose p = track_frame_pose(canted, 100.0, 109.5);
  const double angle = 9.5 / radius, y = radius * (1.0 - std::cos(angle));
  EXPECT_NEAR(p.translation.x(), radius * std::sin(angle), 1e-12);
  EXPECT_NEAR(p.translation.y(), y * std::cos(phi), 1e-12);
  EXPECT_NEAR(p.translation.z(), -y * std::sin(phi), 1e-12);
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(-phi, Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_LT((p.rotation - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(VehicleElementForces, TrackFramesOnStraightTrackAreTranslations) {
  // Straight, level track: the frame at s is the frame at s0 moved by s - s0 along x, unturned.
  const TrackLayout straight;
  const TrackLayout pieces({{TrackSegmentKind::kStraight, 30.0, 0, true, 0}, {TrackSegmentKind::kStraight, 30.0, 0, true, 0}});
  for (const TrackLayout* layout : {&straight, &pieces}) {
    const FramePose p = track_frame_pose(*layout, 12.0, -7.5);
    EXPECT_EQ(p.rotation, Eigen::Matrix3d::Identity());
    EXPECT_NEAR(p.translation.x(), -19.5, 1e-14);
    EXPECT_EQ(p.translation.y(), 0.0);
    EXPECT_EQ(p.translation.z(), 0.0);
  }
}

TEST(VehicleElementForces, TrackFramesAlongAClothoidFollowItsSeries) {
  // A transition of length L from straight track to radius R: curvature u / (R L) at u metres
  // into it, so the heading is u^2 / (2 R L) and, with a = 1 / (2 R L), the position
  // x = sum_n (-1)^n a^2n u^(4n+1) / ((2n)! (4n+1)), y = sum_n (-1)^n a^(2n+1) u^(4n+3) / ((2n+1)! (4n+3))
  // (the Fresnel integrals' series, 8 terms: the next is below 1e-30 m). Seen from the straight
  // 5 m before the transition (the frames there are unturned), to 1e-12 m.
  const double length = 100.0, radius = 500.0;
  const TrackLayout layout({{TrackSegmentKind::kStraight, 50.0, 0, true, 0},
                            {TrackSegmentKind::kTransition, length, 0, true, 0},
                            {TrackSegmentKind::kCurve, 500.0, radius, true, 0}});
  const double a = 1.0 / (2.0 * radius * length);
  for (double u : {3.0, 20.0, 61.5, 100.0}) {
    double x = 0, y = 0, factorial = 1;  // (2n)! then (2n+1)!
    for (int n = 0; n < 8; ++n) {
      const double sign = n % 2 == 0 ? 1.0 : -1.0;
      if (n > 0) factorial *= (2 * n - 1) * (2 * n);
      x += sign * std::pow(a, 2 * n) * std::pow(u, 4 * n + 1) / (factorial * (4 * n + 1));
      y += sign * std::pow(a, 2 * n + 1) * std::pow(u, 4 * n + 3) / (factorial * (2 * n + 1) * (4 * n + 3));
    }
    const FramePose p = track_frame_pose(layout, 45.0, 50.0 + u);
    EXPECT_NEAR(p.translation.x(), 5.0 + x, 1e-12) << u;
    EXPECT_NEAR(p.translation.y(), y, 1e-12) << u;
    EXPECT_NEAR(std::atan2(p.rotation(1, 0), p.rotation(0, 0)), a * u * u, 1e-15) << u;
    // Between two points of the transition, the heading is the integral of the linear curvature.
    EXPECT_NEAR(track_heading_change(layout, 50.0 + u, 160.0), (length * length - u * u) * a + 10.0 / radius, 1e-15)
        << u;
  }
  // Going there and back is the identity, across the straight, the transition and the curve.
  const FramePose there = track_frame_pose(layout, 20.0, 175.0);
  const FramePose back = track_frame_pose(layout, 175.0, 20.0);
  const FramePose round = compose(there, back);
  EXPECT_LT((round.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT(round.translation.cwiseAbs().maxCoeff(), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Kinematics and loads

TEST(VehicleElementForces, ALateralSpringIsUnstretchedAtTheVersineOfTheCurve) {
  // A car body at s_ref and a bogie frame 9.5 m ahead on a 600 m curve, a lateral spring between
  // the car body's point 9.5 m ahead of its centre (at the frame's height) and the frame's centre.
  // The car body runs along its tangent; its point is on the frame's centre line when the car
  // body is displaced by the chord offset: in the car body's plan axes the frame's centre is at
  // (R sin t, R (1 - cos t)), t = 9.5 / R, and its lateral axis is turned by t, so the point
  // (9.5, y) lies on that axis for y = R (1 - cos t) + (9.5 - R sin t) tan t (first order:
  // 9.5^2 / (2 R)).
  const double radius = 600.0, a = 9.5, k = 1e6;
  VehicleDescription v;
  VehicleBody car{"car_body", BodyKind::kCarBody, 40000, {1e5, 1e6, 1e6}, {}, {0, 0, 2.0}, {}};
  VehicleBody frame{"frame", BodyKind::kBogieFrame, 3000, {3000, 3000, 3000}, {}, {a, 0, 0.5}, {}};
  v.bodies = {car, frame};
  VehicleElement spring = element("lateral", ElementKind::kSpringDamper, "car_body", "frame", {a, 0, -1.5}, {0, 0, 0});
  spring.stiffness = {0, k, 0};
  v.elements = {spring};
  const TrackLayout layout({{TrackSegmentKind::kCurve, 1000.0, radius, true, 0.0}});
  const double t = a / radius;
  const double chord = radius * (1 - std::cos(t)) + (a - radius * std::sin(t)) * std::tan(t);
  EXPECT_NEAR(chord, a * a / (2 * radius), 1e-4);  // 0.0752 m; the difference is of order a^4 / R^3
  std::vector<BodyState> q(2);
  q[0].displacement[kBodyLateral] = chord;
  const std::vector<BodyLoads> at = element_loads(v, layout, 200.0, 30.0, q);
  // Zero to 1e-12 m of the chord (R (1 - cos t) loses 1e-13 m to cancellation, the frames'
  // poses carry 1e-14 m).
  EXPECT_NEAR(at[0].force.y(), 0.0, k * 1e-12);
  EXPECT_NEAR(at[1].force.y(), 0.0, k * 1e-12);
  std::printf("[ measured ] chord %.15f m, a^2 / (2 R) = %.15f m; force there %.2e N\n", chord, a * a / (2 * radius),
              at[1].force.y());
  // 1 mm further: the spring's frame (the bogie's) sees the car body's point moved by 1 mm cos t
  // along its y axis; that force along the car body's y is k 1 mm cos^2 t, back.
  const double delta = 1e-3;
  q[0].displacement[kBodyLateral] = chord + delta;
  const std::vector<BodyLoads> off = element_loads(v, layout, 200.0, 30.0, q);
  EXPECT_NEAR(off[0].generalised[kBodyLateral], -k * delta * std::cos(t) * std::cos(t), 1e-9 * k * delta);
  EXPECT_NEAR(off[1].generalised[kBodyLateral], k * delta * std::cos(t), 1e-9 * k * delta);
}

// The elements' loads on all bodies summed in the track frame at s_ref: forces, and moments about
// that frame's origin; with the sums of their magnitudes as scales.
struct Resultant {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double force_scale = 0, moment_scale = 0;
};

Resultant resultant(const VehicleDescription& v, const TrackLayout& layout, double s_ref,
                    const std::vector<BodyState>& q, const std::vector<BodyLoads>& loads) {
  Resultant r;
  for (std::size_t i = 0; i < v.bodies.size(); ++i) {
    const VehicleBody& b = v.bodies[i];
    const FramePose frame = track_frame_pose(layout, s_ref, s_ref + b.position[0]);
    const Eigen::Vector3d centre =
        frame.point({0, b.position[1] + q[i].displacement[kBodyLateral], b.position[2] + q[i].displacement[kBodyVertical]});
    const Eigen::Vector3d f = frame.rotation * loads[i].force;
    const Eigen::Vector3d m = frame.rotation * loads[i].moment + centre.cross(f);
    r.force += f;
    r.moment += m;
    r.force_scale += f.norm();
    r.moment_scale += m.norm();
  }
  return r;
}

TEST(VehicleElementForces, ActionAndReactionBalanceBetweenTheBodies) {
  // Each element between two bodies pushes them apart or together with +F at A's point and -F at
  // B's, and a torsional spring turns them with +M and -M: summed over the bodies, with each
  // body's force and moment about its centre of gravity moved into the track frame at s_ref and
  // taken about that frame's origin, the forces cancel, and the moments leave only each force
  // pair's couple (P_A - P_B) x F, which the test takes from its own kinematics (the points) and
  // the elements' forces. That couple is -d x F: zero when the force lies along the deflection,
  // else of second order (k d^2); the law's axes are the track frame's (docs/vehicle.md), which
  // take it. A random state with rates of the Cooperrider car (with torsional springs, a bump stop
  // and nonlinear dampers) at 40 m/s, in the transition and straddling the curve's start.
  // Rounding of sums of terms up to 1e5 N leaves about 1e-15 relative: asserted to 1e-9 of the
  // sums of magnitudes.
  const VehicleDescription car = linked_car();
  const TrackLayout layout = transition_layout();
  for (double s_ref : {55.0, 100.0, 147.0}) {
    const std::vector<BodyState> q = random_states(car.bodies.size(), 11 + static_cast<unsigned>(s_ref));
    const std::vector<BodyLoads> loads = element_loads(car, layout, s_ref, 40.0, q);
    const std::vector<ElementAction> actions = element_actions(car, layout, s_ref, 40.0, q);
    const Resultant r = resultant(car, layout, s_ref, q, loads);
    Eigen::Vector3d couples = Eigen::Vector3d::Zero();
    for (std::size_t e = 0; e < car.elements.size(); ++e) {
      const Eigen::Vector3d f = track_frame_pose(layout, s_ref, actions[e].station).rotation * actions[e].force;
      const Placed a = place_end(car, layout, s_ref, q, car.elements[e], 0);
      const Placed b = place_end(car, layout, s_ref, q, car.elements[e], 1);
      couples += (a.point - b.point).cross(f);
    }
    EXPECT_GT(r.force_scale, 1e3);  // not balanced by being zero
    EXPECT_LT(r.force.norm(), 1e-9 * r.force_scale) << s_ref;
    EXPECT_LT((r.moment - couples).norm(), 1e-9 * r.moment_scale) << s_ref;
    std::printf("[ measured ] s_ref %g m: |sum F| / sum|F| = %.2e, |sum M - couples| / sum|M| = %.2e, "
                "|couples| / sum|M| = %.2e (sum|F| = %.3g N)\n",
                s_ref, r.force.norm() / r.force_scale, (r.moment - couples).norm() / r.moment_scale,
                couples.norm() / r.moment_scale, r.force_scale);
  }
  // Central forces: every spring made isotropic (k_x = k_y = k_z, so F = k d lies along d), the
  // dampers, bump stops and nonlinear dampers removed, the torsional springs (pure couples) kept.
  // Then the moments about one point cancel as they stand.
  VehicleDescription central = linked_car();
  std::vector<VehicleElement> kept;
  for (VehicleElement e : central.elements) {
    if (e.kind == ElementKind::kBumpStop || e.kind == ElementKind::kNonlinearDamper) continue;
    const double k = (e.stiffness[0] + e.stiffness[1] + e.stiffness[2]) / 3.0;
    e.stiffness = {k, k, k};
    e.damping = {0, 0, 0};
    kept.push_back(e);
  }
  central.elements = kept;
  for (double s_ref : {55.0, 100.0, 147.0}) {
    const std::vector<BodyState> q = random_states(central.bodies.size(), 31 + static_cast<unsigned>(s_ref));
    const Resultant r = resultant(central, layout, s_ref, q, element_loads(central, layout, s_ref, 40.0, q));
    EXPECT_LT(r.force.norm(), 1e-9 * r.force_scale) << s_ref;
    EXPECT_LT(r.moment.norm(), 1e-9 * r.moment_scale) << s_ref;
    std::printf("[ measured ] central forces, s_ref %g m: |sum F| / sum|F| = %.2e, |sum M| / sum|M| = %.2e\n", s_ref,
                r.force.norm() / r.force_scale, r.moment.norm() / r.moment_scale);
  }
}

TEST(VehicleElementForces, SpringsAreConservative) {
  // Springs, torsional springs and bump stops store energy: with the dampers zeroed the
  // generalised forces are minus the gradient of V = sum 1/2 k d^2 + 1/2 k_roll a_x^2 +
  // 1/2 k_yaw a_z^2 + 1/2 k_stop (|d| - clearance)^2 beyond, which this test computes from its
  // own kinematics (Eigen's angle-axis rotations, points moved into the station frames).
  // Central differences with h = 1e-6 (m or rad): the truncation error h^2 V''' / 6 is of order
  // 1e-12 x k x lever^3 (5e6 N/m x 10^3 m^3 at most: 1e-3 N or N m), the rounding eps V / h about
  // 1e-8; asserted to 1e-6 of the body's largest load plus 1e-2 N. The bump stop is kept well
  // beyond its clearance (the car body 40 mm left and the rear frame 5 mm right, against the
  // versine of 22 mm there and small turns) so that the steps do not straddle the kink of its
  // energy. Rates are random and the speed 30 m/s: without dampers they
  // change nothing.
  const VehicleDescription car = springs_only(anchored_car());
  const TrackLayout layout = transition_layout();
  const double s_ref = 97.0, h = 1e-6;
  std::vector<BodyState> q = random_states(car.bodies.size(), 5);
  BodyState& body = q[index_of(car, "car_body")];
  body.displacement[kBodyLateral] = 0.04;
  body.displacement[kBodyRoll] = 0.001;
  body.displacement[kBodyYaw] = 0.0005;
  BodyState& rear = q[index_of(car, "rear_frame")];
  rear.displacement[kBodyLateral] = -0.005;
  rear.displacement[kBodyRoll] = 0.002;
  const std::vector<BodyLoads> loads = element_loads(car, layout, s_ref, 30.0, q);
  double worst = 0;
  for (std::size_t i = 0; i < car.bodies.size(); ++i) {
    const double scale = norm_of(loads[i].generalised);
    for (std::size_t j = 0; j < kBodyCoordinates; ++j) {
      std::vector<BodyState> plus = q, minus = q;
      plus[i].displacement[j] += h;
      minus[i].displacement[j] -= h;
      const double gradient = (potential(car, layout, s_ref, plus) - potential(car, layout, s_ref, minus)) / (2 * h);
      EXPECT_NEAR(loads[i].generalised[j], -gradient, 1e-6 * scale + 1e-2) << car.bodies[i].name << " coordinate " << j;
      worst = std::max(worst, std::abs(loads[i].generalised[j] + gradient) / scale);
    }
  }
  // The bump stop and the torsional springs did work: they are engaged.
  const std::vector<ElementAction> actions = element_actions(car, layout, s_ref, 30.0, q);
  for (std::size_t e = 0; e < car.elements.size(); ++e)
    if (car.elements[e].kind == ElementKind::kBumpStop) {
      EXPECT_GT(std::abs(actions[e].deflection.y()), 0.01);
      EXPECT_GT(std::abs(actions[e].force.y()), 2.5e4);
    }
  std::printf("[ measured ] largest |Q + dV/dq| over the body's largest load: %.2e\n", worst);
}

TEST(VehicleElementForces, NothingChangesAlongAConstantCurve) {
  // On a constant canted curve every track frame is the previous one turned and moved alike, so
  // moving the vehicle by 3.7 m with its state unchanged (rates included) changes no load: to 1e-9
  // of the largest (rounding of the frames' poses, about 1e-14 m and rad, gives 1e-12).
  const VehicleDescription car = anchored_car();
  const TrackLayout layout = transition_layout();
  const std::vector<BodyState> q = random_states(car.bodies.size(), 7);
  const std::vector<BodyLoads> a = element_loads(car, layout, 300.0, 40.0, q);
  const std::vector<BodyLoads> b = element_loads(car, layout, 303.7, 40.0, q);
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double scale = norm_of(a[i].generalised);
    for (std::size_t j = 0; j < kBodyCoordinates; ++j) {
      EXPECT_NEAR(a[i].generalised[j], b[i].generalised[j], 1e-9 * scale) << car.bodies[i].name << " " << j;
      worst = std::max(worst, std::abs(a[i].generalised[j] - b[i].generalised[j]) / scale);
    }
    EXPECT_LT((a[i].force - b[i].force).norm(), 1e-9 * a[i].force.norm());
  }
  std::printf("[ measured ] largest change of a load over 3.7 m of curve: %.2e of the body's largest\n", worst);
  // Riding steadily (no displacement rates) through the curve at speed, no element moves: every
  // deflection rate vanishes, and the dampers carry nothing.
  std::vector<BodyState> steady = q;
  for (BodyState& s : steady) s.rate.fill(0.0);
  const std::vector<ElementAction> actions = element_actions(car, layout, 300.0, 40.0, steady);
  for (std::size_t e = 0; e < actions.size(); ++e) {
    EXPECT_LT(actions[e].deflection_rate.norm(), 1e-13) << car.elements[e].name;
    EXPECT_LT(actions[e].rotation_rate.norm(), 1e-14) << car.elements[e].name;
    if (car.elements[e].kind == ElementKind::kNonlinearDamper ||
        (car.elements[e].kind == ElementKind::kSpringDamper && car.elements[e].stiffness == std::array<double, 3>{})) {
      EXPECT_LT(actions[e].force.norm(), 1e-7) << car.elements[e].name;
    }
  }
}

TEST(VehicleElementForces, InATransitionTheDampersWorkAtSpeed) {
  // Bodies at rest on the track (no displacement, no rate) in an uncanted transition from straight
  // to R = 600 m over 100 m (kappa' = 1 / 60000 m^-2) at V = 40 m/s: the bogie frame 7.5 m ahead
  // of the car body turns against it at (kappa(s_f) - kappa(s_c)) V = kappa' L V, L = 7.5 m, so the
  // yaw damper 1.5 m to the left is stretched at 1.5 kappa' L V = 7.5 mm/s, 1250 N with c =
  // 166669 N s/m, pushing the frame forward (+x) on its left side; and the car body's point over
  // the frame falls outwards, -int_0^L u kappa(s_c + u) du, at -kappa' L^2 V / 2 = 18.75 mm/s, so
  // the lateral damper (c = 29200 N s/m) pulls the frame's point to the right, -547.5 N. The
  // car body 1 m into the transition: the neglected terms are of the relative size of the
  // versine over the lever (2e-3 / 1.5) and of the turn (5e-4): asserted to 0.5 %.
  const VehicleDescription car = read_vehicle_file(kCarFile);
  const TrackLayout layout = transition_layout(0.0);
  const std::vector<BodyState> rest(car.bodies.size());
  const double speed = 40.0, kappa_rate = 1.0 / 60000.0, lever = 7.5;
  const std::vector<ElementAction> actions = element_actions(car, layout, 51.0, speed, rest);
  for (std::size_t e = 0; e < car.elements.size(); ++e) {
    const std::string& name = car.elements[e].name;
    if (name == "front_yaw_damper_left" || name == "front_yaw_damper_right") {
      const double side = name == "front_yaw_damper_left" ? 1.0 : -1.0;
      const double expected = 166669.0 * side * 1.5 * kappa_rate * lever * speed;
      EXPECT_NEAR(actions[e].force.x(), expected, 5e-3 * std::abs(expected)) << name;
      std::printf("[ measured ] %s: %.2f N (first order %.2f N)\n", name.c_str(), actions[e].force.x(), expected);
    }
    if (name == "front_secondary_left") {
      // Its spring (182300 N/m) carries the offset itself, -int_0^L (L - u) kappa(s_c + u) du =
      // -(L^2 / 2 + L^3 / 6) / 60000 = -1.64 mm; the damper the rate.
      const double offset = -(lever * lever / 2 + lever * lever * lever / 6) / 60000.0;
      EXPECT_NEAR(actions[e].deflection.y(), offset, 5e-3 * std::abs(offset)) << name;
      const double expected = -29200.0 * kappa_rate * lever * lever * speed / 2;
      const double damper = actions[e].force.y() - 182300.0 * actions[e].deflection.y();
      EXPECT_NEAR(damper, expected, 5e-3 * std::abs(expected)) << name;
      std::printf("[ measured ] %s: lateral offset %.4f mm (first order %.4f mm), damper %.2f N (first order %.2f N)\n",
                  name.c_str(), 1e3 * actions[e].deflection.y(), 1e3 * offset, damper, expected);
    }
  }
  // The same vehicle at rest (V = 0) or in the constant curve: no damper force at all.
  for (auto [s_ref, v] : {std::pair{51.0, 0.0}, std::pair{400.0, speed}}) {
    for (const ElementAction& a : element_actions(car, layout, s_ref, v, rest))
      EXPECT_LT(a.deflection_rate.norm(), 1e-13) << s_ref << " " << v;
  }
}

TEST(VehicleElementForces, RatesAreTheTimeDerivativesOfTheDeflections) {
  // The deflection rates (and a torsional spring's angle rates) are d/dt of the deflections with
  // the states moving at their rates and the vehicle at V along a canted transition: central
  // differences in time with dt = 1e-5 s (the vehicle moves 0.4 mm, away from the pieces' ends):
  // truncation dt^2 d''' / 6 with d''' of order (V kappa)^2 rates ~ 1e-8, rounding 1e-15 x 20 m /
  // dt = 2e-9 m/s; asserted to 1e-7 m/s and rad/s.
  const VehicleDescription car = anchored_car();
  const TrackLayout layout = transition_layout();
  const double s_ref = 96.3, speed = 40.0, dt = 1e-5;
  const std::vector<BodyState> q = random_states(car.bodies.size(), 3);
  auto moved = [&](double t) {
    std::vector<BodyState> m = q;
    for (BodyState& s : m)
      for (std::size_t j = 0; j < kBodyCoordinates; ++j) s.displacement[j] += t * s.rate[j];
    return element_actions(car, layout, s_ref + speed * t, speed, m);
  };
  const std::vector<ElementAction> now = element_actions(car, layout, s_ref, speed, q);
  const std::vector<ElementAction> later = moved(dt), earlier = moved(-dt);
  double worst = 0;
  for (std::size_t e = 0; e < now.size(); ++e) {
    const Eigen::Vector3d d = (later[e].deflection - earlier[e].deflection) / (2 * dt);
    EXPECT_LT((now[e].deflection_rate - d).cwiseAbs().maxCoeff(), 1e-7) << car.elements[e].name;
    worst = std::max(worst, (now[e].deflection_rate - d).cwiseAbs().maxCoeff());
    if (car.elements[e].kind == ElementKind::kTorsionalSpring) {
      const Eigen::Vector3d r = (later[e].rotation - earlier[e].rotation) / (2 * dt);
      EXPECT_LT((now[e].rotation_rate - r).cwiseAbs().maxCoeff(), 1e-7) << car.elements[e].name;
      worst = std::max(worst, (now[e].rotation_rate - r).cwiseAbs().maxCoeff());
    }
  }
  std::printf("[ measured ] largest |rate - central difference|: %.2e m/s or rad/s\n", worst);
}

TEST(VehicleElementForces, AMirroredStateMirrorsTheLoads) {
  // The Cooperrider car with its added elements is symmetric about its centre plane. On straight
  // track, negating every body's y, roll and yaw (and their rates) mirrors the state, so the
  // lateral, roll and yaw loads change sign and the vertical and pitch ones stay: to 1e-12 of the
  // largest load (the sums run over the left and right elements in another order).
  const VehicleDescription car = linked_car();
  const TrackLayout straight;
  const std::vector<BodyState> q = random_states(car.bodies.size(), 23);
  std::vector<BodyState> m = q;
  for (BodyState& s : m)
    for (std::size_t j : {kBodyLateral, kBodyRoll, kBodyYaw}) {
      s.displacement[j] = -s.displacement[j];
      s.rate[j] = -s.rate[j];
    }
  const std::vector<BodyLoads> a = element_loads(car, straight, 12.0, 40.0, q);
  const std::vector<BodyLoads> b = element_loads(car, straight, 12.0, 40.0, m);
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double scale = norm_of(a[i].generalised);
    EXPECT_GT(scale, 1.0);
    for (std::size_t j = 0; j < kBodyCoordinates; ++j) {
      const double sign = j == kBodyLateral || j == kBodyRoll || j == kBodyYaw ? -1.0 : 1.0;
      EXPECT_NEAR(b[i].generalised[j], sign * a[i].generalised[j], 1e-12 * scale) << car.bodies[i].name << " " << j;
      worst = std::max(worst, std::abs(b[i].generalised[j] - sign * a[i].generalised[j]) / scale);
    }
  }
  std::printf("[ measured ] largest mirror mismatch: %.2e of the body's largest load\n", worst);
}

TEST(VehicleElementForces, ATorsionalSpringSeesTheTrackTurnAndCant) {
  // Two bodies 7.5 m apart, both in their nominal positions, a torsional spring between them.
  // On an uncanted 600 m curve the front one is turned by 7.5 / 600 rad against the rear one
  // (exactly: the track frames differ by that rotation about z): yaw moment k 0.0125 rad on the
  // rear body (A) and minus it on the front one (B), to 1e-12.
  VehicleDescription v;
  v.bodies = {VehicleBody{"rear", BodyKind::kCarBody, 4e4, {1e5, 1e6, 1e6}, {}, {0, 0, 2.0}, {}},
              VehicleBody{"front", BodyKind::kBogieFrame, 3e3, {3e3, 3e3, 3e3}, {}, {7.5, 0, 0.5}, {}}};
  VehicleElement t = element("t", ElementKind::kTorsionalSpring, "rear", "front", {7.5, 0, -1.5}, {0, 0, 0});
  t.yaw_stiffness = 1e6;
  t.roll_stiffness = 2e6;
  v.elements = {t};
  const std::vector<BodyState> rest(2);
  const TrackLayout curve({{TrackSegmentKind::kCurve, 1000.0, 600.0, true, 0.0}});
  const double turn = 7.5 / 600.0;
  const ElementAction a = element_actions(v, curve, 100.0, 30.0, rest)[0];
  EXPECT_NEAR(a.rotation.z(), turn, 1e-15);
  EXPECT_NEAR(a.rotation.x(), 0.0, 1e-15);
  const std::vector<BodyLoads> loads = element_loads(v, curve, 100.0, 30.0, rest);
  EXPECT_NEAR(loads[0].generalised[kBodyYaw], 1e6 * turn, 1e-12 * 1e6 * turn);
  EXPECT_NEAR(loads[1].generalised[kBodyYaw], -1e6 * turn, 1e-12 * 1e6 * turn);
  EXPECT_NEAR(loads[1].generalised[kBodyRoll], 0.0, 1e-9);
  // In a canted transition (100 m to 600 m and a cant angle of -asin(0.1) rad), between 60 and
  // 67.5 m: the relative roll is the cant difference, 7.5 / 100 x (-asin 0.1), and the relative
  // yaw the heading difference int kappa = (17.5^2 - 10^2) / (2 x 60000) turned about the rear
  // body's rolled z axis, so times the cosine of the cant there (0.1 x -asin 0.1: a change of
  // 9e-8 rad); each to 1e-7 rad (the rotations' non-commuting, of the order of the product of the
  // heading and cant steps times the cant, 1.3e-5 x 0.01, is left out).
  const TrackLayout transition = transition_layout();
  const ElementAction c = element_actions(v, transition, 60.0, 30.0, rest)[0];
  const double cant_step = 7.5 / 100.0 * -std::asin(0.1);
  const double heading = (17.5 * 17.5 - 10.0 * 10.0) / (2.0 * 60000.0);
  EXPECT_NEAR(c.rotation.x(), cant_step, 1e-7);
  EXPECT_NEAR(c.rotation.z(), heading * std::cos(0.1 * -std::asin(0.1)), 1e-7);
  std::printf("[ measured ] canted transition: roll %.9f rad (cant step %.9f), yaw %.9f rad (heading %.9f)\n",
              c.rotation.x(), cant_step, c.rotation.z(), heading);
  // Rolling the front body by the opposite of that step unloads the roll spring (to first order).
  std::vector<BodyState> compensated(2);
  compensated[1].displacement[kBodyRoll] = -cant_step;
  EXPECT_NEAR(element_actions(v, transition, 60.0, 30.0, compensated)[0].rotation.x(), 0.0, 1e-5);
}

TEST(VehicleElementForces, BumpStopAndNonlinearDamperLaws) {
  // The laws as docs/vehicle.md states them. A bump stop with 20 mm clearance and 1e6 N/m: free
  // within +-20 mm, then 1e6 N/m times the travel beyond, restoring. A damper curve (0, 0),
  // (0.1 m/s, 5 kN), (0.3 m/s, 7 kN): on the points, linear between, the last slope (10 kN s/m)
  // beyond, odd.
  EXPECT_EQ(bump_stop_force(0.02, 1e6, 0.0), 0.0);
  EXPECT_EQ(bump_stop_force(0.02, 1e6, 0.015), 0.0);
  EXPECT_EQ(bump_stop_force(0.02, 1e6, -0.02), 0.0);
  EXPECT_NEAR(bump_stop_force(0.02, 1e6, 0.035), 15000.0, 1e-9);
  EXPECT_NEAR(bump_stop_force(0.02, 1e6, -0.035), -15000.0, 1e-9);
  EXPECT_NEAR(bump_stop_force(0.0, 1e6, -0.001), -1000.0, 1e-9);
  const std::vector<std::pair<double, double>> curve{{0, 0}, {0.1, 5000}, {0.3, 7000}};
  EXPECT_EQ(nonlinear_damper_force(curve, 0.0), 0.0);
  EXPECT_NEAR(nonlinear_damper_force(curve, 0.1), 5000.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, 0.3), 7000.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, 0.05), 2500.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, 0.2), 6000.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, 0.5), 9000.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, -0.2), -6000.0, 1e-9);
  EXPECT_NEAR(nonlinear_damper_force(curve, -0.5), -9000.0, 1e-9);

  // The same through the bodies: a frame over a wheelset on straight track, a lateral bump stop
  // and a lateral damper between them. The frame 35 mm to the left: the stop pushes it back with
  // 15 kN and the wheelset to the left with as much. The frame moving left at 0.2 m/s: the damper
  // holds it back with 6 kN.
  VehicleDescription v;
  v.bodies = {VehicleBody{"ws", BodyKind::kWheelset, 1000, {600, 80, 600}, {}, {0, 0, 0.46}, {}},
              VehicleBody{"frame", BodyKind::kBogieFrame, 2000, {1000, 1000, 1500}, {}, {0, 0, 0.6}, {}}};
  VehicleElement stop = element("stop", ElementKind::kBumpStop, "ws", "frame", {0, 0, 0.1}, {0, 0, -0.04});
  stop.direction = 1;
  stop.clearance = 0.02;
  stop.stop_stiffness = 1e6;
  VehicleElement damper = element("damper", ElementKind::kNonlinearDamper, "ws", "frame", {0, 0, 0.1}, {0, 0, -0.04});
  damper.direction = 1;
  damper.curve = curve;
  v.elements = {stop, damper};
  std::vector<BodyState> q(2);
  q[1].displacement[kBodyLateral] = 0.035;
  std::vector<BodyLoads> loads = element_loads(v, TrackLayout(), 0.0, 30.0, q);
  EXPECT_NEAR(loads[1].generalised[kBodyLateral], -15000.0, 1e-6);
  EXPECT_NEAR(loads[0].generalised[kBodyLateral], 15000.0, 1e-6);
  q[1].displacement[kBodyLateral] = -0.015;
  loads = element_loads(v, TrackLayout(), 0.0, 30.0, q);
  EXPECT_EQ(loads[1].generalised[kBodyLateral], 0.0);
  q[1].rate[kBodyLateral] = 0.2;
  loads = element_loads(v, TrackLayout(), 0.0, 30.0, q);
  EXPECT_NEAR(loads[1].generalised[kBodyLateral], -6000.0, 1e-6);
  // The force acts 0.04 m below the frame's centre of gravity: (r x F)_x = -r_z F_y = -240 N m.
  EXPECT_NEAR(loads[1].generalised[kBodyRoll], -(-0.04) * -6000.0, 1e-6);
  // A state for every body, or nothing.
  EXPECT_THROW(element_loads(v, TrackLayout(), 0.0, 30.0, std::vector<BodyState>(1)), std::invalid_argument);
}

TEST(VehicleElementForces, ElementsToTheTrackFollowIt) {
  // The Cooperrider bogie under a body that follows the track (parameters/vehicles/
  // cooperrider-bogie.json): its secondary elements are tied to the track frame at the frame's
  // distance. With the frame at its static deflection (17.074 mm down, as the file says), anywhere
  // (straight, transition with cant, curve) and at any speed, they are unstretched and still: the
  // body that follows the track moves with it.
  const VehicleDescription bogie = read_vehicle_file(kBogieFile);
  const TrackLayout layout = transition_layout();
  std::vector<BodyState> rest(bogie.bodies.size());
  rest[0].displacement[kBodyVertical] = -0.017074;
  for (double s_ref : {20.0, 90.0, 400.0}) {
    const std::vector<ElementAction> actions = element_actions(bogie, layout, s_ref, 50.0, rest);
    for (std::size_t e = 0; e < actions.size(); ++e) {
      if (bogie.elements[e].bodies[1] != kTrackBody) continue;
      EXPECT_LT(actions[e].deflection.norm(), 1e-15) << bogie.elements[e].name << " at " << s_ref;  // 0.6584 - 0.017074 exactly
      EXPECT_LT(actions[e].deflection_rate.norm(), 1e-15) << bogie.elements[e].name << " at " << s_ref;
    }
  }
}

}  // namespace
}  // namespace wrc
