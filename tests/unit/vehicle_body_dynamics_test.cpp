// SPDX-License-Identifier: Apache-2.0
// A rigid body's equations of motion in its moving track frame (core/vehicle/body_dynamics.hpp),
// against physics rather than the code: Lagrange's equations by finite differences of a kinetic
// energy the test builds from the body's absolute motion (its track frame's pose in a fixed frame
// from track_frame_pose(), differentiated along the track; its own orientation from Eigen's
// angle-axis rotations and their derivatives), on a canted curve and in a transition; steady
// curving at and off the balanced speed against the closed forms worked out here; free
// oscillations of the Cooperrider car body on springs to the track, integrated by the test's own
// fixed-step RK4: the bounce frequency and the conservation of energy on straight track and of the
// Jacobi integral on a curve; mirror symmetry between a left and a right curve; bad input.
#include "core/vehicle/body_dynamics.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/vehicle/element_forces.hpp"
#include "core/vehicle/track_frames.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "expect_invalid.hpp"

namespace wrc {
namespace {

const std::string kCarFile = std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-car.json";
constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;  // [m/s^2]

using Vector5 = Eigen::Matrix<double, 5, 1>;

// Straight 50 m, a 100 m transition (curvature and cant linear), a 600 m curve to the left with
// 0.15 m cant (the right rail raised: cant angle -asin(0.1)), 1000 m long.
TrackLayout transition_layout() {
  return TrackLayout({{TrackSegmentKind::kStraight, 50.0, 0, true, 0},
                      {TrackSegmentKind::kTransition, 100.0, 0, true, 0},
                      {TrackSegmentKind::kCurve, 1000.0, 600.0, true, 0.15}});
}

// A curve of radius 600 m to the left (or right) with 0.15 m cant from the start, 3000 m long.
TrackLayout curve_layout(bool left = true, double cant = 0.15, double radius = 600.0) {
  return TrackLayout({{TrackSegmentKind::kCurve, 3000.0, radius, left, cant}});
}

VehicleBody car_body() {
  const VehicleDescription car = read_vehicle_file(kCarFile);
  return *car.body("car_body");
}

// The car body with products of inertia and off the centre line, so that every term counts.
VehicleBody skewed_body() {
  VehicleBody b = car_body();
  b.products_of_inertia = {1.5e4, -2.0e4, 8.0e3};
  b.inertia = {2.8e5, 4.5e5, 5.0e5};
  b.position = {3.0, 0.2, 2.0596};
  return b;
}

Eigen::Matrix3d hat(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

// The test's own kinematics: the orientation from Eigen's angle-axis rotations (yaw about z, then
// pitch about the turned y, then roll about the twice turned x) and its derivative in each angle:
// d/dyaw = [e_z] R, d/dpitch = Rz [e_y] Ry Rx, d/droll = R [e_x].
Eigen::Matrix3d orientation(const std::array<double, 5>& q) {
  return (Eigen::AngleAxisd(q[kBodyYaw], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(q[kBodyPitch], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(q[kBodyRoll], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Matrix3d orientation_rate(const std::array<double, 5>& q, const std::array<double, 5>& rate) {
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(q[kBodyYaw], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d ry = Eigen::AngleAxisd(q[kBodyPitch], Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d rx = Eigen::AngleAxisd(q[kBodyRoll], Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d r = rz * ry * rx;
  return rate[kBodyYaw] * hat(Eigen::Vector3d::UnitZ()) * r +
         rate[kBodyPitch] * rz * hat(Eigen::Vector3d::UnitY()) * ry * rx +
         rate[kBodyRoll] * r * hat(Eigen::Vector3d::UnitX());
}

// The track frame at s_b + sigma in the frame at s_b, differentiated in sigma at 0 by the
// five-point central difference with a step of 2^-7 m: truncation (2^-7)^4 / 30 times the fifth
// derivative (of the order of kappa^5, nil), rounding 1e-16 / 2^-7 of the pose's 1e-16 m. The
// step is a power of 2 so that s_b + sigma is exact: with a step like 1e-2 the distances' rounding
// changes the step by 1e-12 of itself as s_b crosses a power of 2, and T (mostly 1/2 m V^2)
// by 2e-12 of itself, a jump of 1e-4 J.
struct FrameRate {
  Eigen::Matrix3d rotation;     // [1/m]
  Eigen::Vector3d translation;  // [-]
};

FrameRate frame_rate(const TrackLayout& layout, double s_b) {
  const double h = 1.0 / 128;
  const FramePose m2 = track_frame_pose(layout, s_b, s_b - 2 * h), m1 = track_frame_pose(layout, s_b, s_b - h);
  const FramePose p1 = track_frame_pose(layout, s_b, s_b + h), p2 = track_frame_pose(layout, s_b, s_b + 2 * h);
  FrameRate r;
  r.rotation = (m2.rotation - 8 * m1.rotation + 8 * p1.rotation - p2.rotation) / (12 * h);
  r.translation = (m2.translation - 8 * m1.translation + 8 * p1.translation - p2.translation) / (12 * h);
  return r;
}

// The body's kinetic energy [J] from its absolute motion. The fixed frame is the track frame at
// s_b frozen at this instant (T is the same in every frame at rest): the centre of gravity is at
// A(s) c + o(s), the orientation A(s) R(q), with s = s_ref + X moving at V.
double kinetic_energy(const VehicleBody& b, const TrackLayout& layout, double s_ref, double speed,
                      const std::array<double, 5>& q, const std::array<double, 5>& rate) {
  const double s_b = s_ref + b.position[0];
  const FrameRate f = frame_rate(layout, s_b);
  const Eigen::Vector3d c(0, b.position[1] + q[kBodyLateral], b.position[2] + q[kBodyVertical]);
  const Eigen::Vector3d v =
      speed * (f.rotation * c + f.translation) + Eigen::Vector3d(0, rate[kBodyLateral], rate[kBodyVertical]);
  const Eigen::Matrix3d r = orientation(q);
  const Eigen::Matrix3d r_rate = speed * f.rotation * r + orientation_rate(q, rate);
  const Eigen::Matrix3d w = r_rate * r.transpose();
  const Eigen::Vector3d omega(0.5 * (w(2, 1) - w(1, 2)), 0.5 * (w(0, 2) - w(2, 0)), 0.5 * (w(1, 0) - w(0, 1)));
  const auto& i = b.inertia;
  const auto& p = b.products_of_inertia;
  Eigen::Matrix3d tensor;
  tensor << i[0], -p[0], -p[1], -p[0], i[1], -p[2], -p[1], -p[2], i[2];
  return 0.5 * b.mass * v.squaredNorm() + 0.5 * omega.dot(r * tensor * r.transpose() * omega);
}

double five_point(double m2, double m1, double p1, double p2, double h) { return (m2 - 8 * m1 + 8 * p1 - p2) / (12 * h); }

// Lagrange's d/dt(dT/dq'_k) - dT/dq_k along q(t) = q + q' t (q'' = 0), at t = 0. dT/dq'_k by a
// central difference with a step of 1 (exact: T is quadratic in q'), its time derivative and
// dT/dq_k by five-point differences (steps 1e-2 s and 1e-3).
Vector5 lagrange(const VehicleBody& b, const TrackLayout& layout, double s_ref, double speed, const BodyState& s) {
  auto momentum = [&](double t, std::size_t k) {
    std::array<double, 5> q = s.displacement, up = s.rate, down = s.rate;
    for (std::size_t j = 0; j < 5; ++j) q[j] += s.rate[j] * t;
    up[k] += 1.0;
    down[k] -= 1.0;
    return 0.5 * (kinetic_energy(b, layout, s_ref + speed * t, speed, q, up) -
                  kinetic_energy(b, layout, s_ref + speed * t, speed, q, down));
  };
  auto energy = [&](std::size_t k, double dq) {
    std::array<double, 5> q = s.displacement;
    q[k] += dq;
    return kinetic_energy(b, layout, s_ref, speed, q, s.rate);
  };
  Vector5 l;
  const double dt = 1e-2, dq = 1e-3;
  for (std::size_t k = 0; k < 5; ++k) {
    const double dp = five_point(momentum(-2 * dt, k), momentum(-dt, k), momentum(dt, k), momentum(2 * dt, k), dt);
    const double dtq = five_point(energy(k, -2 * dq), energy(k, -dq), energy(k, dq), energy(k, 2 * dq), dq);
    l[static_cast<Eigen::Index>(k)] = dp - dtq;
  }
  return l;
}

// The mass matrix as the Hessian of T in q': exact by central differences (step 1) as T is
// quadratic in q'.
Eigen::Matrix<double, 5, 5> hessian(const VehicleBody& b, const TrackLayout& layout, double s_ref, double speed,
                                    const BodyState& s) {
  Eigen::Matrix<double, 5, 5> m;
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < 5; ++j) {
      auto t = [&](double di, double dj) {
        std::array<double, 5> r = s.rate;
        r[i] += di;
        r[j] += dj;
        return kinetic_energy(b, layout, s_ref, speed, s.displacement, r);
      };
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          (t(1, 1) - t(1, -1) - t(-1, 1) + t(-1, -1)) / 4.0;
    }
  return m;
}

// Displacements up to 50 mm and 0.3 rad, rates up to 0.2 m/s and 0.5 rad/s: far from small.
BodyState random_state(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  BodyState s;
  for (std::size_t j = 0; j < kBodyCoordinates; ++j) {
    const bool angle = j >= kBodyRoll;
    s.displacement[j] = (angle ? 0.3 : 0.05) * u(random);
    s.rate[j] = (angle ? 0.5 : 0.2) * u(random);
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Lagrange's equations

TEST(VehicleBodyDynamics, InertialForcesAreLagrangesOfTheAbsoluteKineticEnergy) {
  // The body (the Cooperrider car body with products of inertia, 3 m ahead of the reference point
  // and 0.2 m off the centre line) at random states with large angles and rates, at 40 m/s, on a
  // 600 m curve with 0.15 m cant and in a transition to it (the twist changes along the track):
  // h equals d/dt(dT/dq') - dT/dq at q'' = 0 and M the Hessian of T in q', T from the absolute
  // motion as the test builds it. Error budget: the five-point differences' truncation is nil
  // ((step x rate)^4 / 30 < 1e-10 of the terms); rounding dominates, 1e-16 of T (3.6e7 J, mostly
  // 1/2 m V^2) over the 1e-3 step, 5e-6 N, and the frame rate's (1e-16 / 2^-7 of m V |c|) over
  // the 1e-2 s step, 7e-6 N. Tolerance 1e-3 N (N m), 1e-8 of the largest term; M's Hessian is
  // exact but for 1e-16 of T, 4e-9 kg (kg m^2): tolerance 1e-6.
  const VehicleBody body = skewed_body();
  const double speed = 40.0;
  std::mt19937 random(7);
  double worst_h = 0, worst_m = 0, largest = 0;
  struct Case {
    TrackLayout layout;
    double s_ref;
    const char* name;
  };
  const std::vector<Case> cases{{curve_layout(), 500.0, "curve"}, {transition_layout(), 90.0, "transition"}};
  for (const Case& c : cases) {
    for (int n = 0; n < 4; ++n) {
      const BodyState s = random_state(random);
      const BodyDynamics d = body_dynamics(body, c.layout, c.s_ref, speed, s);
      const Vector5 l = lagrange(body, c.layout, c.s_ref, speed, s);
      const Eigen::Matrix<double, 5, 5> m = hessian(body, c.layout, c.s_ref, speed, s);
      for (Eigen::Index k = 0; k < 5; ++k) {
        EXPECT_NEAR(d.inertial[k], l[k], 1e-3) << c.name << " " << n << " coordinate " << k;
        worst_h = std::max(worst_h, std::abs(d.inertial[k] - l[k]));
        largest = std::max(largest, std::abs(l[k]));
        for (Eigen::Index j = 0; j < 5; ++j) {
          EXPECT_NEAR(d.mass_matrix(k, j), m(k, j), 1e-6) << c.name << " " << n << " " << k << ", " << j;
          worst_m = std::max(worst_m, std::abs(d.mass_matrix(k, j) - m(k, j)));
        }
      }
    }
  }
  EXPECT_GT(largest, 1e4);  // the terms are not all small
  std::printf("[ measured ] |h - Lagrange| <= %.2e N (N m), largest term %.3e; |M - Hessian of T| <= %.2e\n", worst_h,
              largest, worst_m);
}

// ---------------------------------------------------------------------------------------------
// Steady curving

TEST(VehicleBodyDynamics, SteadyCurvingBalancesAtTheBalancedSpeed) {
  // A body at rest in its track frame (q = q' = 0) on a 600 m left-hand curve with 0.15 m cant
  // (phi = asin(0.1), the right rail raised: cant angle -phi). Its centre of gravity runs on a
  // horizontal circle about the curve's centre, at the horizontal distance d = Y cos(phi) +
  // Z sin(phi) nearer to it than the centre line (Y = 0 here), so its acceleration is
  // V^2 kappa (1 - kappa d) towards the centre, horizontal: in the track frame
  // (0, cos(phi), sin(phi)) for a left-hand curve (y left, z up, the frame rolled by -phi).
  // Gravity and inertia together, Q_gravity - h, then are, with g along -(0, -sin(phi), cos(phi)):
  //   y:  m g sin(phi) - m V^2 kappa (1 - kappa d) cos(phi)
  //   z: -m g cos(phi) - m V^2 kappa (1 - kappa d) sin(phi)
  // At the balanced speed V^2 kappa = g tan(phi) and at rail level (d = 0): y = 0 and
  // z = -m g / cos(phi), the track carries the weight over the cosine. At height Z the centre of
  // gravity runs on a circle smaller by Z sin(phi): y = m g sin(phi) kappa d (14.9 N for the car
  // body). At another speed, at rail level: y = -m (V^2/R cos(phi) - g sin(phi)), outwards
  // (to the right, -y) with a cant deficiency. Each to 1e-10 of m g (a few roundings).
  const double radius = 600.0, kappa = 1.0 / radius;
  const double phi = std::asin(0.1);
  const TrackLayout layout = curve_layout(true, 0.15, radius);
  const double balanced = std::sqrt(kG * std::tan(phi) * radius);
  EXPECT_NEAR(balanced, TrackLayout::balanced_speed(layout.segments()[0], 1.5, kG), 1e-12);
  VehicleBody body = car_body();
  const double m = body.mass, tol = 1e-10 * m * kG;
  const BodyState rest;

  body.position = {0, 0, 0};
  BodyDynamics d = body_dynamics(body, layout, 200.0, balanced, rest);
  BodyVector q = d.gravity - d.inertial;
  EXPECT_NEAR(q[kBodyLateral], 0.0, tol);
  EXPECT_NEAR(q[kBodyVertical], -m * kG / std::cos(phi), tol);
  std::printf("[ measured ] balanced speed %.4f m/s at rail level: y %.2e N, z %.6f N (-m g / cos(phi) = %.6f N)\n",
              balanced, q[kBodyLateral], q[kBodyVertical], -m * kG / std::cos(phi));
  for (double speed : {0.0, 0.5 * balanced, 1.3 * balanced, 2.0 * balanced}) {
    d = body_dynamics(body, layout, 200.0, speed, rest);
    q = d.gravity - d.inertial;
    EXPECT_NEAR(q[kBodyLateral], -m * (speed * speed / radius * std::cos(phi) - kG * std::sin(phi)), tol) << speed;
    EXPECT_NEAR(q[kBodyVertical], -m * (kG * std::cos(phi) + speed * speed / radius * std::sin(phi)), tol) << speed;
  }

  body.position = {0, 0, 2.0596};
  const double dist = body.position[2] * std::sin(phi);
  d = body_dynamics(body, layout, 200.0, balanced, rest);
  q = d.gravity - d.inertial;
  EXPECT_NEAR(q[kBodyLateral], m * kG * std::sin(phi) * kappa * dist, tol);
  EXPECT_NEAR(q[kBodyVertical], -m * kG * std::cos(phi) - m * balanced * balanced * kappa * (1 - kappa * dist) *
                                                              std::sin(phi), tol);
  std::printf("[ measured ] car body's centre of gravity 2.0596 m up at the balanced speed: y %.4f N (expected %.4f N)\n",
              q[kBodyLateral], m * kG * std::sin(phi) * kappa * dist);

  // The frame turns at Omega = V kappa (0, -sin(phi), cos(phi)): a body with I_yy != I_zz at rest
  // feels the gyroscopic moment Omega x I Omega = V^2 kappa^2 (-sin cos)(I_zz - I_yy) e_x, so
  // h_roll is that and the other moments vanish.
  body.inertia = {2.8e5, 4.0e5, 5.0e5};
  d = body_dynamics(body, layout, 200.0, balanced, rest);
  const double gyro = balanced * balanced * kappa * kappa * -std::sin(phi) * std::cos(phi) * (5.0e5 - 4.0e5);
  EXPECT_NEAR(d.inertial[kBodyRoll], gyro, 1e-9 * std::abs(gyro));
  EXPECT_NEAR(d.inertial[kBodyYaw], 0.0, 1e-12);
  EXPECT_NEAR(d.inertial[kBodyPitch], 0.0, 1e-12);
  EXPECT_EQ(d.gravity[kBodyRoll], 0.0);

  // The external force: its y and z in the track frame, as they are; F_x has no coordinate.
  body.external_force = {1234.0, -2.0e4, -1.5e5};
  d = body_dynamics(body, layout, 200.0, balanced, rest);
  EXPECT_EQ(d.external[kBodyLateral], -2.0e4);
  EXPECT_EQ(d.external[kBodyVertical], -1.5e5);
  for (std::size_t k : {kBodyRoll, kBodyYaw, kBodyPitch}) EXPECT_EQ(d.external[static_cast<Eigen::Index>(k)], 0.0);
}

// ---------------------------------------------------------------------------------------------
// Free oscillations

// The Cooperrider car body alone on four springs to the track at its secondary suspension's
// corners (x = +-7.5 m, y = +-1.2 m, 1.4012 m below its centre of gravity), each with the file's
// secondary stiffnesses, lateral 1.823e5 N/m and vertical 3.333e5 N/m, no damping. The track
// points stand m g / (4 k_z) above the body's points, so gravity is balanced at q = 0 on straight
// track.
constexpr double kLateral = 1.823e5, kVertical = 3.333e5;

VehicleDescription car_on_springs() {
  VehicleDescription v;
  v.name = "car body on springs";
  v.bodies = {car_body()};
  const VehicleBody& b = v.bodies[0];
  const double preload = b.mass * kG / (4 * kVertical);
  for (double x : {7.5, -7.5})
    for (double y : {1.2, -1.2}) {
      VehicleElement e;
      e.name = std::string(x > 0 ? "front" : "rear") + (y > 0 ? "_left" : "_right");
      e.kind = ElementKind::kSpringDamper;
      e.bodies = {b.name, kTrackBody};
      e.attachments = {{{x, y, -1.4012}, {x, b.position[1] + y, b.position[2] - 1.4012 + preload}}};
      e.stiffness = {0, kLateral, kVertical};
      v.elements.push_back(e);
    }
  return v;
}

struct Motion {
  double s_ref;
  BodyState state;
};

// One classical RK4 step of the body's equations, the elements' loads from element_loads().
void rk4_step(const VehicleDescription& v, const TrackLayout& layout, double speed, double h, Motion& x) {
  auto derivative = [&](double s_ref, const BodyState& s) {
    const std::vector<BodyLoads> loads = element_loads(v, layout, s_ref, speed, {s});
    return body_accelerations(v.bodies[0], layout, s_ref, speed, s, loads[0].generalised, kG);
  };
  auto shifted = [](const BodyState& s, const std::array<double, 5>& dq, const std::array<double, 5>& dv, double f) {
    BodyState r = s;
    for (std::size_t j = 0; j < 5; ++j) {
      r.displacement[j] += f * dq[j];
      r.rate[j] += f * dv[j];
    }
    return r;
  };
  const BodyState& s0 = x.state;
  const std::array<double, 5> a1 = derivative(x.s_ref, s0);
  const BodyState s1 = shifted(s0, s0.rate, a1, 0.5 * h);
  const std::array<double, 5> a2 = derivative(x.s_ref + 0.5 * h * speed, s1);
  const BodyState s2 = shifted(s0, s1.rate, a2, 0.5 * h);
  const std::array<double, 5> a3 = derivative(x.s_ref + 0.5 * h * speed, s2);
  const BodyState s3 = shifted(s0, s2.rate, a3, h);
  const std::array<double, 5> a4 = derivative(x.s_ref + h * speed, s3);
  for (std::size_t j = 0; j < 5; ++j) {
    x.state.displacement[j] += h / 6 * (s0.rate[j] + 2 * s1.rate[j] + 2 * s2.rate[j] + s3.rate[j]);
    x.state.rate[j] += h / 6 * (a1[j] + 2 * a2[j] + 2 * a3[j] + a4[j]);
  }
  x.s_ref += h * speed;
}

// The springs' energy [J] from the elements' deflections, and gravity's, m g times the height of
// the centre of gravity (the track frame at s_b rolled by the cant there, its origin at rail
// level, no gradient).
double potential_energy(const VehicleDescription& v, const TrackLayout& layout, double s_ref, const BodyState& s) {
  double u = 0;
  const std::vector<ElementAction> actions = element_actions(v, layout, s_ref, 0.0, {s});
  for (std::size_t e = 0; e < actions.size(); ++e)
    for (int j = 0; j < 3; ++j)
      u += 0.5 * v.elements[e].stiffness[static_cast<std::size_t>(j)] * actions[e].deflection[j] *
           actions[e].deflection[j];
  const VehicleBody& b = v.bodies[0];
  const double cant = layout.at(s_ref + b.position[0]).cant_angle;
  const double y = b.position[1] + s.displacement[kBodyLateral], z = b.position[2] + s.displacement[kBodyVertical];
  return u + b.mass * kG * (std::sin(cant) * y + std::cos(cant) * z);
}

// The largest angular frequency [rad/s] of the linearised motion about q = 0 on straight track:
// the stiffness by central differences of the generalised forces (step 1e-6), M at 0.
double highest_frequency(const VehicleDescription& v) {
  const TrackLayout straight;
  Eigen::Matrix<double, 5, 5> k;
  for (std::size_t j = 0; j < 5; ++j) {
    BodyState up, down;
    up.displacement[j] = 1e-6;
    down.displacement[j] = -1e-6;
    const auto fu = element_loads(v, straight, 0.0, 0.0, {up})[0].generalised;
    const auto fd = element_loads(v, straight, 0.0, 0.0, {down})[0].generalised;
    for (std::size_t i = 0; i < 5; ++i)
      k(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = -(fu[i] - fd[i]) / 2e-6;
  }
  const BodyMatrix m = body_dynamics(v.bodies[0], straight, 0.0, 0.0, BodyState{}).mass_matrix;
  const Eigen::Matrix<double, 5, 5> a = m.inverse() * k;
  return std::sqrt(a.eigenvalues().real().maxCoeff());
}

TEST(VehicleBodyDynamics, TheCarBodyBouncesAtItsSpringsFrequency) {
  // Pure bounce on straight track at 40 m/s: the car body 10 mm above its rest position, all else
  // at rest, stays in bounce (the springs are symmetric) at f = sqrt(4 k_z / m) / (2 pi)
  // (0.8722 Hz). RK4 with 2 ms steps for 20 s; the period from the upward crossings of z = 0
  // (linear interpolation, exact to O(h^3) where z'' = -omega^2 z vanishes). RK4's relative
  // frequency error is (omega h)^4 / 120 = 7e-13, so far within the 1e-3 asked: 1e-9 asserted.
  // The other coordinates stay at 0 but for rounding (1e-12).
  const VehicleDescription v = car_on_springs();
  const TrackLayout straight;
  const double m = v.bodies[0].mass;
  const double expected = std::sqrt(4 * kVertical / m) / (2 * kPi);
  Motion x{0.0, BodyState{}};
  x.state.displacement[kBodyVertical] = 0.01;
  const double h = 2e-3;
  std::vector<double> crossings;
  double worst_other = 0;
  for (int n = 0; n < 10000; ++n) {
    const double z0 = x.state.displacement[kBodyVertical];
    rk4_step(v, straight, 40.0, h, x);
    const double z1 = x.state.displacement[kBodyVertical];
    if (z0 < 0 && z1 >= 0) crossings.push_back((n + z0 / (z0 - z1)) * h);
    for (std::size_t j : {kBodyLateral, kBodyRoll, kBodyYaw, kBodyPitch})
      worst_other = std::max(worst_other, std::abs(x.state.displacement[j]));
  }
  ASSERT_GE(crossings.size(), 10u);
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  const double frequency = 1.0 / period;
  EXPECT_NEAR(frequency, expected, 1e-9 * expected);
  EXPECT_LT(worst_other, 1e-12);
  std::printf("[ measured ] bounce %.10f Hz, sqrt(4 k_z / m) / (2 pi) = %.10f Hz, relative error %.2e\n", frequency,
              expected, std::abs(frequency - expected) / expected);
}

// The body's rest position on the layout at speed V (constant curve or straight): where the
// accelerations vanish at zero rates, by Newton's method with a difference Jacobian (step 1e-7).
BodyState rest_position(const VehicleDescription& v, const TrackLayout& layout, double s_ref, double speed) {
  auto accelerations = [&](const BodyState& s) {
    const std::vector<BodyLoads> loads = element_loads(v, layout, s_ref, speed, {s});
    const auto a = body_accelerations(v.bodies[0], layout, s_ref, speed, s, loads[0].generalised, kG);
    return Vector5(a[0], a[1], a[2], a[3], a[4]);
  };
  BodyState s;
  for (int iteration = 0; iteration < 8; ++iteration) {
    const Vector5 f = accelerations(s);
    Eigen::Matrix<double, 5, 5> jacobian;
    for (std::size_t j = 0; j < 5; ++j) {
      BodyState up = s;
      up.displacement[j] += 1e-7;
      jacobian.col(static_cast<Eigen::Index>(j)) = (accelerations(up) - f) / 1e-7;
    }
    const Vector5 step = jacobian.partialPivLu().solve(-f);
    for (std::size_t j = 0; j < 5; ++j) s.displacement[j] += step[static_cast<Eigen::Index>(j)];
  }
  return s;
}

// Runs the car body on springs from a random state about its rest position for `steps` RK4
// steps and returns the largest change of the conserved quantity, E = T + U (straight) or the
// Jacobi integral T2 - T0 + U (curve; T2, T0 the parts of T quadratic in and free of q'),
// relative to the oscillation's energy, the quantity's value above that at rest. T from the
// absolute motion (kinetic_energy()).
double energy_drift(const TrackLayout& layout, double speed, double h, int steps, double* oscillation) {
  const VehicleDescription v = car_on_springs();
  const VehicleBody& b = v.bodies[0];
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const BodyState rest = rest_position(v, layout, 200.0, speed);
  Motion x{200.0, rest};
  for (std::size_t j = 0; j < 5; ++j) {
    x.state.displacement[j] += (j >= kBodyRoll ? 0.005 : 0.01) * u(random);
    x.state.rate[j] = (j >= kBodyRoll ? 0.02 : 0.05) * u(random);
  }
  auto conserved = [&](const Motion& m) {
    std::array<double, 5> back;
    for (std::size_t j = 0; j < 5; ++j) back[j] = -m.state.rate[j];
    const double t = kinetic_energy(b, layout, m.s_ref, speed, m.state.displacement, m.state.rate);
    const double t_back = kinetic_energy(b, layout, m.s_ref, speed, m.state.displacement, back);
    const double t0 = kinetic_energy(b, layout, m.s_ref, speed, m.state.displacement, std::array<double, 5>{});
    const double t2 = 0.5 * (t + t_back) - t0;
    return t2 - t0 + potential_energy(v, layout, m.s_ref, m.state);
  };
  const double start = conserved(x);
  *oscillation = start - conserved(Motion{200.0, rest});
  double worst = 0;
  for (int n = 0; n < steps; ++n) {
    rk4_step(v, layout, speed, h, x);
    worst = std::max(worst, std::abs(conserved(x) - start));
  }
  return worst / *oscillation;
}

TEST(VehicleBodyDynamics, UndampedMotionConservesEnergyOnStraightTrackAndTheJacobiIntegralOnACurve) {
  // The car body on its undamped springs, started off its rest position (10 mm, 5 mrad, 0.05 m/s,
  // 0.02 rad/s), 10 s at 40 m/s with RK4 steps of 2 ms. On straight track the frame is inertial and
  // E = T + U is conserved; on a constant 600 m curve with 0.15 m cant the frame turns steadily,
  // the Lagrangian does not depend on time and the Jacobi integral T2 - T0 + U is. Tolerance:
  // RK4 damps a linear mode of frequency omega by (omega h)^6 / 72 of its energy per step, so the
  // oscillation's energy by N (omega h)^6 / 72 at most over N steps, omega the highest mode's
  // (from the equations linearised on straight track); twice that (the modes shift a little on
  // the curve, the motion is not quite linear), plus 1e-9 for rounding in the energies (1e-16 of
  // 1/2 m V^2 = 3.6e7 J against the oscillation's hundreds of J) and the frame rates in T.
  const double h = 2e-3;
  const int steps = 5000;
  const double omega = highest_frequency(car_on_springs());
  const double bound = 2.0 * steps * std::pow(omega * h, 6) / 72.0 + 1e-9;
  double scale = 0;
  const double straight = energy_drift(TrackLayout(), 40.0, h, steps, &scale);
  EXPECT_LT(straight, bound);
  std::printf("[ measured ] highest mode %.3f rad/s; straight: energy drift %.2e of %.3f J (bound %.2e)\n", omega,
              straight, scale, bound);
  const double curve = energy_drift(curve_layout(), 40.0, h, steps, &scale);
  EXPECT_LT(curve, bound);
  std::printf("[ measured ] curve: Jacobi integral drift %.2e of %.3f J (bound %.2e)\n", curve, scale, bound);
}

// ---------------------------------------------------------------------------------------------
// Symmetry

TEST(VehicleBodyDynamics, AMirroredCurveAndStateMirrorTheTerms) {
  // A body symmetric about its x-z plane (the car body, with I_xz != 0 which the mirror keeps) on
  // a left curve and on the mirrored right curve (and transitions to them), at a state and its
  // mirror image (y, roll, yaw and their rates negated): h, Q_gravity mirror (y, roll, yaw
  // negated), M keeps sign(i) sign(j) M_ij. Exact but for rounding: 1e-12 of the largest term.
  VehicleBody body = car_body();
  body.products_of_inertia = {0.0, -2.0e4, 0.0};
  std::mt19937 random(3);
  const std::array<double, 5> sign{-1, 1, -1, -1, 1};
  double worst = 0;
  for (int kind = 0; kind < 2; ++kind) {
    const TrackLayout left = kind == 0 ? curve_layout(true) : transition_layout();
    const TrackLayout right =
        kind == 0 ? curve_layout(false)
                  : TrackLayout({{TrackSegmentKind::kStraight, 50.0, 0, true, 0},
                                 {TrackSegmentKind::kTransition, 100.0, 0, true, 0},
                                 {TrackSegmentKind::kCurve, 1000.0, 600.0, false, 0.15}});
    for (int n = 0; n < 3; ++n) {
      const BodyState s = random_state(random);
      BodyState mirrored = s;
      for (std::size_t j = 0; j < 5; ++j) {
        mirrored.displacement[j] *= sign[j];
        mirrored.rate[j] *= sign[j];
      }
      const BodyDynamics a = body_dynamics(body, left, 95.0, 40.0, s);
      const BodyDynamics b = body_dynamics(body, right, 95.0, 40.0, mirrored);
      const double scale = std::max(a.inertial.cwiseAbs().maxCoeff(), a.mass_matrix.cwiseAbs().maxCoeff());
      for (Eigen::Index i = 0; i < 5; ++i) {
        const double si = sign[static_cast<std::size_t>(i)];
        EXPECT_NEAR(b.inertial[i], si * a.inertial[i], 1e-12 * scale) << kind << " " << i;
        EXPECT_NEAR(b.gravity[i], si * a.gravity[i], 1e-12 * body.mass * kG) << kind << " " << i;
        worst = std::max(worst, std::abs(b.inertial[i] - si * a.inertial[i]) / scale);
        for (Eigen::Index j = 0; j < 5; ++j)
          EXPECT_NEAR(b.mass_matrix(i, j), si * sign[static_cast<std::size_t>(j)] * a.mass_matrix(i, j),
                      1e-12 * scale);
      }
    }
  }
  std::printf("[ measured ] largest mirror mismatch of h: %.2e of the largest term\n", worst);
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(VehicleBodyDynamics, BadInputIsRefusedNamingTheValue) {
  // A non-finite state, s_ref, speed or force, a negative gravity, a pitch of pi/2 (the angles'
  // axes are singular) and, for the whole vehicle, states or loads that do not match the bodies:
  // each refused with std::invalid_argument naming the body, the key and the value.
  const VehicleBody body = car_body();
  const TrackLayout layout = curve_layout();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  BodyState s;
  s.displacement[kBodyYaw] = nan;
  test::expect_invalid([&] { body_dynamics(body, layout, 10.0, 30.0, s); },
                       {"body 'car_body'", "displacement[yaw]", "nan", "not a finite number"});
  s = BodyState{};
  s.rate[kBodyLateral] = -inf;
  test::expect_invalid([&] { body_dynamics(body, layout, 10.0, 30.0, s); }, {"rate[y]", "-inf"});
  s = BodyState{};
  test::expect_invalid([&] { body_dynamics(body, layout, nan, 30.0, s); }, {"s_ref", "nan"});
  test::expect_invalid([&] { body_dynamics(body, layout, 10.0, inf, s); }, {"speed", "inf"});
  test::expect_invalid([&] { body_dynamics(body, layout, 10.0, 30.0, s, -9.81); }, {"gravity", "-9.81"});
  std::array<double, 5> forces{};
  forces[kBodyPitch] = nan;
  test::expect_invalid([&] { body_accelerations(body, layout, 10.0, 30.0, s, forces); },
                       {"element_forces[pitch]", "nan"});
  s.displacement[kBodyPitch] = kPi / 2;
  test::expect_invalid([&] { body_accelerations(body, layout, 10.0, 30.0, s, std::array<double, 5>{}); },
                       {"displacement[pitch]", "singular"});

  VehicleDescription v;
  v.bodies = {body};
  test::expect_invalid(
      [&] { body_accelerations(v, layout, 10.0, 30.0, std::vector<BodyState>(2), std::vector<BodyLoads>(1)); },
      "2 body states for 1 bodies");
  test::expect_invalid(
      [&] { body_accelerations(v, layout, 10.0, 30.0, std::vector<BodyState>(1), std::vector<BodyLoads>(3)); },
      "3 body loads for 1 bodies");
  // And a good call through the vehicle: at rest on straight track with nothing holding it the
  // body falls at g.
  const auto a =
      body_accelerations(v, TrackLayout(), 10.0, 30.0, std::vector<BodyState>(1), std::vector<BodyLoads>(1));
  EXPECT_NEAR(a[0][kBodyVertical], -kG, 1e-14);
  EXPECT_EQ(a[0][kBodyLateral], 0.0);
}

}  // namespace
}  // namespace wrc
