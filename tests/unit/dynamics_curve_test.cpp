// SPDX-License-Identifier: Apache-2.0
// The wheelset on a track layout (core/track, docs/track.md): the layout's curvature and cant
// along the distance (continuous through transitions, the signs of the conventions), its file
// (round trip, errors naming the file, segment and key), and the dynamics in curves: a free
// wheelset in a large-radius curve settles where it rolls purely, delta_r = 2 r0 e / R; at the
// balanced speed of a canted curve the wheelset stays on its treads and the lateral contact force
// balances only the suspension; a left-hand curve mirrors a right-hand one; straight track is the
// straight-track run bit for bit; a cant ramp adds no slip (the contact query takes the rates
// relative to the track frame, checked against the slip of a wheel over a twisted rail).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "core/dynamics/wheelset_equations.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/track/track_layout_file.hpp"
#include <initializer_list>
#include <string>
#include "expect_invalid.hpp"
#include "run_to_end.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

TrackSegment straight(double length) { return {TrackSegmentKind::kStraight, length, 0, true, 0}; }
TrackSegment transition(double length) { return {TrackSegmentKind::kTransition, length, 0, true, 0}; }
TrackSegment curve(double length, double radius, bool left, double cant) {
  return {TrackSegmentKind::kCurve, length, radius, left, cant};
}

using test::expect_invalid;

std::shared_ptr<ContactEvaluator> interp_contact() {
  static const std::shared_ptr<const ContactModel> model = make_contact_model("interp", test::s1002_uic60_geometry());
  return std::make_shared<InProcessContact>(model);
}

std::vector<WheelsetSnapshot> run(WheelsetSimulation& sim) { return test::run_to_end(sim); }

// Straight 100 m, transition 50 m, left curve R 600 m with 0.1 m cant for 200 m, transition 50 m,
// straight: the curvature and the cant angle ramp linearly and continuously, with the signs of
// docs/conventions.md (left curve: kappa > 0; its outer, right rail raised: a negative roll).
TEST(TrackLayout, CurvatureAndCantAreContinuousThroughTransitions) {
  const TrackLayout layout({straight(100), transition(50), curve(200, 600, true, 0.1), transition(50), straight(100)});
  EXPECT_DOUBLE_EQ(layout.length(), 500.0);
  const double phi = -std::asin(0.1 / 1.5);
  EXPECT_TRUE(layout.at(50).straight());
  EXPECT_DOUBLE_EQ(layout.at(125).curvature, 0.5 / 600);  // half-way up the ramp
  EXPECT_DOUBLE_EQ(layout.at(125).cant_angle, 0.5 * phi);
  EXPECT_DOUBLE_EQ(layout.at(125).curvature_rate, 1.0 / 600 / 50);
  EXPECT_DOUBLE_EQ(layout.at(125).cant_angle_rate, phi / 50);
  EXPECT_DOUBLE_EQ(layout.at(250).curvature, 1.0 / 600);
  EXPECT_DOUBLE_EQ(layout.at(250).cant_angle, phi);
  EXPECT_EQ(layout.at(250).curvature_rate, 0.0);
  EXPECT_DOUBLE_EQ(layout.at(375).curvature, 0.5 / 600);  // down the exit ramp
  EXPECT_DOUBLE_EQ(layout.at(375).curvature_rate, -1.0 / 600 / 50);
  EXPECT_TRUE(layout.at(450).straight());
  EXPECT_TRUE(layout.at(1e4).straight());  // past the end it goes on straight
  // No jump anywhere: sampled every 0.1 m, neighbouring values differ by at most one ramp step.
  for (double s = 0; s < 500; s += 0.1) {
    EXPECT_LE(std::abs(layout.at(s + 0.1).curvature - layout.at(s).curvature), 0.1 / 600 / 50 * (1 + 1e-9)) << s;
    EXPECT_LE(std::abs(layout.at(s + 0.1).cant_angle - layout.at(s).cant_angle), 0.1 * std::abs(phi) / 50 * (1 + 1e-9))
        << s;
  }
  // A right-hand curve mirrors it.
  const TrackLayout right({straight(100), transition(50), curve(200, 600, false, 0.1)});
  EXPECT_DOUBLE_EQ(right.at(250).curvature, -1.0 / 600);
  EXPECT_DOUBLE_EQ(right.at(250).cant_angle, -phi);
  // Balanced speed sqrt(g R tan(phi)) and cant deficiency b V^2 / (g R) - h.
  const TrackSegment c = curve(200, 600, true, 0.1);
  const double v = TrackLayout::balanced_speed(c, 1.5, 9.81);
  EXPECT_NEAR(v, std::sqrt(9.81 * 600 * 0.1 / std::sqrt(1.5 * 1.5 - 0.01)), 1e-12);
  EXPECT_NEAR(TrackLayout::cant_deficiency(c, 1.5, 30.0, 9.81), 1.5 * 900 / (9.81 * 600) - 0.1, 1e-12);
}

TEST(TrackLayout, BadLayoutsNameTheSegmentAndTheValue) {
  expect_invalid([] { TrackLayout({straight(100), curve(100, 600, true, 0)}); }, {"segment 2 (curve)", "transition"});
  expect_invalid([] { TrackLayout({curve(100, 600, true, 0), straight(100)}); }, {"segment 2 (straight)"});
  expect_invalid([] { TrackLayout({straight(100), transition(10), curve(100, 20, true, 0)}); },
                 {"segment 3 (curve)", "radius 20"});
  expect_invalid([] { TrackLayout({curve(100, 600, true, 0.3)}); }, {"segment 1 (curve)", "cant 0.3"});
  expect_invalid([] { TrackLayout({straight(-1)}); }, {"segment 1 (straight)", "length -1"});
  expect_invalid([] { TrackLayout({straight(10), transition(5), transition(5)}); }, {"segment 2", "another transition"});
}

TEST(TrackLayoutFile, RoundTripAndErrorsNamingFileSegmentAndKey) {
  const TrackLayout layout({straight(100.5), transition(60), curve(300, 650.25, false, 0.125), transition(60)}, 1.5);
  const TrackLayout back = parse_track_layout(track_layout_text(layout), "t.json");
  ASSERT_EQ(back.segments().size(), 4u);
  for (double s = 0; s < 600; s += 7.3) {
    EXPECT_EQ(back.at(s).curvature, layout.at(s).curvature) << s;
    EXPECT_EQ(back.at(s).cant_angle, layout.at(s).cant_angle) << s;
  }
  expect_invalid([] { parse_track_layout("{\"segments\": []}", "t.json"); }, {"t.json", "segments"});
  expect_invalid([] { parse_track_layout("{\"segments\": [{\"type\": \"curve\", \"length\": 5}]}", "t.json"); },
                 {"t.json: segments[0]: radius: missing"});
  expect_invalid(
      [] { parse_track_layout("{\"segments\": [{\"type\": \"loop\", \"length\": 5}]}", "t.json"); },
      {"t.json: segments[0]: type", "loop"});
  expect_invalid(
      [] { parse_track_layout("{\"segments\": [{\"type\": \"straight\", \"length\": 5, \"length\": 6}]}", "t.json"); },
      {"t.json", "length: duplicate key"});
  expect_invalid(
      [] { parse_track_layout("{\"segments\": [{\"type\": \"straight\", \"length\": 5, \"radius\": 6}]}", "t.json"); },
      {"t.json: segments[0]: radius: a key of a curve, not a key of a straight"});
  expect_invalid(
      [] { parse_track_layout("{\"segments\": [{\"type\": \"straight\", \"length\": 5, \"bank\": 6}]}", "t.json"); },
      {"t.json: segments[0]: bank: not a key of a straight"});
  expect_invalid([] { parse_track_layout("{\"segments\": [{\"type\": \"straight\", \"length\": 1e999}]}", "t.json"); },
                 {"t.json"});
  expect_invalid(
      [] {
        parse_track_layout(
            "{\"segments\": [{\"type\": \"curve\", \"length\": 5, \"radius\": 10, \"direction\": \"left\"}]}", "t.json");
      },
      {"t.json: segment 1 (curve): radius 10"});
}

// A free wheelset (no springs, no lateral load) at 5 m/s in a left-hand curve of 1500 m without
// cant, starting in the curve: it steers radially and runs where the rolling-radius difference
// lets it roll round the curve, delta_r = 2 r0 e / R with e half the lateral distance of the
// contact points (pure rolling). Lateral and yaw dampers to the track frame damp the kinematic
// oscillation and act on no steady state (no rate relative to the track there). What is left
// over is the creepage that carries the small centrifugal force (m_total V^2 / R, 0.17 % of the
// load) and the spin: bound 5 % of 2 r0 e / R.
TEST(WheelsetInCurve, FreeWheelsetRollsPurelyRoundALargeCurve) {
  RunSpec spec;
  spec.wheelset.suspension = PrimarySuspension::none();
  spec.wheelset.suspension.lateral_damping = 1e5;
  spec.wheelset.suspension.longitudinal_damping = 1e5;
  spec.wheelset.lateral_force = 0.0;
  spec.wheelset.speed = 5.0;
  spec.track = TrackLayout({curve(1000, 1500, true, 0.0)});
  spec.integrator.t_end = 60.0;  // 300 m: the damped kinematic oscillation has died out
  spec.integrator.output_period = 0.01;
  WheelsetSimulation sim(spec, interp_contact(), kR0);
  const std::vector<WheelsetSnapshot> out = run(sim);
  ASSERT_FALSE(out.empty());
  // The wheelset keeps a small oscillation (about 0.3 mm) about its steady state: the rolling-radius
  // difference and the contact points' half distance averaged over the last 30 s (about 20 periods).
  const RigidWheelsetSolver solver(*test::s1002_uic60_geometry());
  double delta_r = 0.0, e = 0.0, y = 0.0;
  int n = 0;
  for (const WheelsetSnapshot& s : out) {
    if (s.t < 30.0) continue;
    const RigidContact rc = solver.solve(s.y, s.yaw);
    delta_r += rc.delta_r();
    e += 0.5 * (rc.left().wheel_point.y() - rc.right().wheel_point.y());
    y += s.y;
    ++n;
  }
  ASSERT_GT(n, 100);
  delta_r /= n;
  e /= n;
  y /= n;
  const double pure = 2.0 * kR0 * e / 1500.0;
  std::cout << "[ measured ] free wheelset in R = 1500 m at 5 m/s, mean of the last 30 s: y = " << y * 1e3
            << " mm, delta_r = " << delta_r * 1e6 << " um, 2 r0 e / R = " << pure * 1e6 << " um\n";
  // The outer (right) wheel rolls the longer way: the wheelset shifts outwards, towards -y, until
  // r_left - r_right = -2 r0 e / R.
  EXPECT_LT(y, 0.0);
  EXPECT_NEAR(delta_r, -pure, 0.05 * pure);
}

// The benchmark wheelset without lateral load through a straight, a 30 m transition and a curve of
// 600 m with 0.1 m cant at 20 m/s, once turning left and once right: the runs mirror each other
// (y, roll and yaw change sign, the wheels swap).
TEST(WheelsetInCurve, ALeftHandCurveMirrorsARightHandOne) {
  std::vector<WheelsetSnapshot> runs[2];
  for (int k = 0; k < 2; ++k) {
    RunSpec spec;
    spec.wheelset.lateral_force = 0.0;
    spec.wheelset.speed = 20.0;
    spec.track = TrackLayout({straight(10), transition(30), curve(500, 600, k == 0, 0.1)});
    spec.integrator.t_end = 3.0;
    spec.integrator.output_period = 0.01;
    WheelsetSimulation sim(spec, interp_contact(), kR0);
    runs[k] = run(sim);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  // Positions to 1e-7 (the integrator's tolerances, 1e-8 m absolute and 1e-6 relative, summed over
  // a few hundred steps that differ in rounding); the rigid normal forces (algebraic unknowns that
  // follow each run's own steps) in the rms to 1e-4 of the static wheel load (measured 0.001 N of
  // 87 kN; 0.43 N with the frame's roll rate in the contact query).
  double largest = 0.0, force_rms = 0.0;
  for (std::size_t i = 0; i < runs[0].size(); ++i) {
    const WheelsetSnapshot& l = runs[0][i];
    const WheelsetSnapshot& r = runs[1][i];
    largest = std::max(largest, std::abs(l.y));
    EXPECT_NEAR(l.y, -r.y, 1e-7) << l.t;
    EXPECT_NEAR(l.roll, -r.roll, 1e-7) << l.t;
    EXPECT_NEAR(l.yaw, -r.yaw, 1e-7) << l.t;
    EXPECT_NEAR(l.z, r.z, 1e-7) << l.t;
    const double d = l.wheels[0].normal_force - r.wheels[1].normal_force;
    force_rms += d * d;
  }
  force_rms = std::sqrt(force_rms / static_cast<double>(runs[0].size()));
  std::cout << "[ measured ] mirrored curves: largest |y| " << largest * 1e3 << " mm, normal force rms difference "
            << force_rms << " N\n";
  EXPECT_LT(force_rms, 1e-4 * 0.5 * RunSpec{}.wheelset.total_vertical_load());
  EXPECT_GT(largest, 1e-4);  // the curve moved the wheelset [m]
}

// The benchmark wheelset without lateral load through 50 m of straight, a 60 m transition and a
// left-hand curve of 1200 m with 0.1 m cant. At the curve's balanced speed (28.0 m/s) the cant
// carries the centrifugal force: the wheelset runs on its treads (both contact angles below
// 0.1 rad, measured 0.02 / 0.07), shifted outwards only as far as the rolling-radius difference of
// the curve asks (-0.53 mm). At 1.6 times that speed (cant deficiency 0.13 m) the outer wheel
// runs at its flange root (-4.99 mm, 0.30 rad). Through the transition, whose ends are kinks of
// the cant ramp, no force jumps: between two outputs 2 ms apart neither normal force changes by
// more than 0.1 % of the static wheel load (measured 13.5 N, 0.016 %; the outer wheel's force
// swings by 1 kN over the run). The contact query's rates are relative to the track frame: with
// the frame's roll rate p_t = V d(cant)/ds in them the ramp added a spurious lateral creepage
// p_t y_c sin(g) / V that switched on and off at its ends, 114 N steps; without the centre's
// -p_t z too (a lateral creepage p_t r0 / V) the steps were 2.3 kN.
TEST(WheelsetInCurve, AtTheBalancedSpeedTheCantCarriesTheCurve) {
  const TrackSegment c = curve(1000, 1200, true, 0.1);
  const double v_balanced = TrackLayout::balanced_speed(c, 1.5, 9.81);
  ASSERT_NEAR(v_balanced, 28.0, 0.1);
  double y_end[2], angle_outer[2], angle_inner[2], largest_step = 0.0, swing = 0.0;
  const double wheel_load = 0.5 * RunSpec{}.wheelset.total_vertical_load();
  for (int k = 0; k < 2; ++k) {
    RunSpec spec;
    spec.wheelset.lateral_force = 0.0;
    spec.wheelset.speed = (k == 0 ? 1.0 : 1.6) * v_balanced;
    spec.track = TrackLayout({straight(50), transition(60), c});
    spec.integrator.t_end = 200.0 / spec.wheelset.speed;  // 90 m into the curve
    spec.integrator.output_period = 2e-3;
    WheelsetSimulation sim(spec, interp_contact(), kR0);
    const std::vector<WheelsetSnapshot> out = run(sim);
    ASSERT_GT(out.size(), 10u);
    y_end[k] = out.back().y;
    angle_inner[k] = out.back().wheels[0].contact_angle;
    angle_outer[k] = out.back().wheels[1].contact_angle;
    if (k == 0) {
      double low = 1e300, high = -1e300;
      for (std::size_t i = 1; i < out.size(); ++i) {
        for (int w = 0; w < 2; ++w)
          largest_step =
              std::max(largest_step, std::abs(out[i].wheels[w].normal_force - out[i - 1].wheels[w].normal_force));
        low = std::min(low, out[i].wheels[1].normal_force);
        high = std::max(high, out[i].wheels[1].normal_force);
      }
      swing = high - low;
    }
  }
  std::cout << "[ measured ] balanced speed " << v_balanced << " m/s: y = " << y_end[0] * 1e3
            << " mm, contact angles " << angle_inner[0] << " / " << angle_outer[0] << " rad; 1.6 times: y = "
            << y_end[1] * 1e3 << " mm, " << angle_inner[1] << " / " << angle_outer[1]
            << " rad; largest normal force step " << largest_step << " N, outer wheel's swing " << swing << " N\n";
  EXPECT_LT(std::abs(angle_inner[0]), 0.1);
  EXPECT_LT(std::abs(angle_outer[0]), 0.1);
  EXPECT_LT(y_end[0], 0.0);
  EXPECT_GT(y_end[0], -3e-3);
  EXPECT_LT(y_end[1], -4e-3);
  // Towards the flange root: past the tread's angles (< 0.1 rad), within the flange-root jump's
  // band, where the table shares the outer wheel's load between tread and flange root (measured
  // 0.16 rad at y = -4.81 mm, 0.18 mm before the jump; the flange root alone has 0.3 rad).
  EXPECT_GT(std::abs(angle_outer[1]), 0.15);
  EXPECT_LT(largest_step, 1e-3 * wheel_load);
  EXPECT_GT(swing, 2.0 * largest_step);
}

// The kinematics behind WheelsetEquations::query on a cant ramp (docs/track.md, "The frame's
// rates in the contact"), checked without the code: a rail twisted about the centre line at rail
// level, X(s, u) = s e_x + Rx(k s) p(u) (k = d(cant)/ds of the 1 km track's ramps, p a circle of
// 50 mm radius whose normal at the contact has the angle g), and a wheel (a cone about its axle,
// radius 0.46 m at the contact) that follows the track frame's screw motion (V along x, roll k V
// about the x axis) and rolls at V / radius: its relative rates are 0, so the query gives it no
// slip. The true contact point (normals aligned, closest points, by Newton) lies ahead of the axle,
// where the wheel's material velocity is tangent to the rail (normal slip 0) and its longitudinal
// slip 0. Its lateral slip over V in the rail's true tangent plane is -k z_c / cos(g) (z_c the
// contact's height above the twist axis: the rail's heading there), to 1 % (measured 4e-4), not the
// k (y_c sin(g) - z_c cos(g)) that the query with the frame's roll rate gave (6.4e-4 on a 70 deg
// flange).
TEST(TrackFrame, AWheelFollowingTheFrameOverATwistedRailSlipsOnlyByTheRailsHeading) {
  using Eigen::Vector3d;
  const double k = std::asin(0.13 / 1.5) / 90.0;  // [rad/m]
  const double v = 30.0, rho0 = 0.46, rail_radius = 0.05;
  const Vector3d ex(1, 0, 0), ey(0, 1, 0);
  auto roll = [](double a, const Vector3d& p) -> Vector3d {
    return Vector3d(p.x(), std::cos(a) * p.y() - std::sin(a) * p.z(), std::sin(a) * p.y() + std::cos(a) * p.z());
  };
  struct Case {
    double angle, y_c, z_c;  // [rad, m, m]
  };
  for (const Case& c : {Case{0.0, 0.75, 0.0}, Case{0.05, 0.75, -3e-4}, Case{0.3, 0.72, -2e-3},
                        Case{1.2217, 0.715, -0.012}, Case{1.2217, -0.715, -0.012}, Case{1.2217, 0.715, 0.0}}) {
    const double g = c.angle;
    const Vector3d centre_of_rail(0, c.y_c - rail_radius * std::sin(g), c.z_c - rail_radius * std::cos(g));
    auto rail = [&](double s, double u) -> Vector3d {
      return Vector3d(s, 0, 0) + roll(k * s, centre_of_rail + rail_radius * Vector3d(0, std::sin(u), std::cos(u)));
    };
    const Vector3d axle_centre(0, c.y_c, c.z_c + rho0);
    auto radius = [&](double w) -> double { return rho0 + std::tan(g) * w; };
    auto wheel = [&](double theta, double w) -> Vector3d {
      return axle_centre + Vector3d(-radius(w) * std::sin(theta), w, -radius(w) * std::cos(theta));
    };
    const double h = 1e-7;
    auto rail_s = [&](double s, double u) -> Vector3d { return (rail(s + h, u) - rail(s - h, u)) / (2 * h); };
    auto rail_u = [&](double s, double u) -> Vector3d { return (rail(s, u + h) - rail(s, u - h)) / (2 * h); };
    auto conditions = [&](const Eigen::Vector4d& x) -> Eigen::Vector4d {  // x = (theta, w, s, u)
      const Vector3d d = wheel(x[0], x[1]) - rail(x[2], x[3]);
      const Vector3d n = rail_s(x[2], x[3]).cross(rail_u(x[2], x[3]));
      const Vector3d wheel_theta = (wheel(x[0] + h, x[1]) - wheel(x[0] - h, x[1])) / (2 * h);
      const Vector3d wheel_w = (wheel(x[0], x[1] + h) - wheel(x[0], x[1] - h)) / (2 * h);
      return Eigen::Vector4d(d.dot(rail_s(x[2], x[3])), d.dot(rail_u(x[2], x[3])), wheel_theta.dot(n),
                             wheel_w.dot(n));
    };
    Eigen::Vector4d x(0, 0, 0, g);
    for (int iteration = 0; iteration < 30; ++iteration) {
      Eigen::Matrix4d jacobian;
      for (int j = 0; j < 4; ++j) {
        Eigen::Vector4d step = Eigen::Vector4d::Zero();
        step[j] = 1e-8;
        jacobian.col(j) = (conditions(x + step) - conditions(x - step)) / 2e-8;
      }
      const Eigen::Vector4d dx = jacobian.partialPivLu().solve(-conditions(x));
      x += dx;
      if (dx.cwiseAbs().maxCoeff() < 1e-15) break;
    }
    ASSERT_LT(std::abs(x[3] - g), 1e-2) << g;  // the contact near the point meant
    const Vector3d point = wheel(x[0], x[1]);
    const double spin = v / radius(x[1]);
    const Vector3d slip = v * ex + k * v * ex.cross(point) + spin * ey.cross(point - axle_centre);
    const Vector3d t1 = rail_s(x[2], x[3]).normalized();
    const Vector3d n = rail_s(x[2], x[3]).cross(rail_u(x[2], x[3])).normalized();
    Vector3d t2 = n.cross(t1);
    if (t2.dot(rail_u(x[2], x[3])) < 0) t2 = -t2;  // along the cross-section's tangent (0, y_u, z_u)
    const double lateral = slip.dot(t2) / v;
    const double heading = -k * c.z_c / std::cos(g);
    const double with_frame_roll = k * (-c.z_c * std::cos(g) - c.y_c * std::sin(g));
    std::cout << "[ measured ] contact angle " << g << " rad, y_c " << c.y_c << " m, z_c " << c.z_c
              << " m: lateral creepage " << lateral << " (-k z_c / cos g " << heading
              << "; the query with the frame's roll rate " << with_frame_roll << "), normal " << slip.dot(n) / v
              << ", longitudinal " << slip.dot(t1) / v << "\n";
    EXPECT_NEAR(lateral, heading, 0.01 * std::abs(heading) + 1e-8) << g;
    EXPECT_LT(std::abs(slip.dot(n) / v), 1e-8) << g;
    EXPECT_LT(std::abs(slip.dot(t1) / v), 1e-6) << g;
  }
}

// The lateral creepage of each wheel at every output of a run (the contact model evaluated again
// at the output's state, where the run's equations put the track then).
struct WheelCreepages {
  double s = 0;                     // distance travelled [m]
  std::array<double, 2> lateral{};  // xi_y of the left and right wheel's patch [-]
  std::array<double, 2> angle{};    // contact angles [rad]
};
std::vector<WheelCreepages> lateral_creepages(const WheelsetSimulation& sim, const ContactModel& model,
                                              const std::vector<WheelsetSnapshot>& out) {
  WheelsetEquations equations = sim.equations();
  std::vector<WheelCreepages> creepages;
  for (const WheelsetSnapshot& snapshot : out) {
    const double s = sim.spec().wheelset.speed * snapshot.t;
    equations.set_track(sim.spec().track.at(s));
    double y[kRigidUnknowns] = {snapshot.y,       snapshot.z,        snapshot.roll,     snapshot.yaw,
                                snapshot.y_dot,   snapshot.z_dot,    snapshot.roll_dot, snapshot.yaw_dot,
                                snapshot.spin_rate,
                                snapshot.wheels[0].normal_force / equations.force_scale(),
                                snapshot.wheels[1].normal_force / equations.force_scale(), 0.0, 0.0};
    FollowedBranches branches;
    branches.tracked_s = {snapshot.wheels[0].s_wheel, snapshot.wheels[1].s_wheel};
    const ContactResult c = model.evaluate(equations.query(ContactFormulation::kRigid, y, branches));
    WheelCreepages w;
    w.s = s;
    for (const ContactPatch& patch : c.patches) {
      const std::size_t i = static_cast<std::size_t>(patch.point.side);
      w.lateral[i] = patch.creepages.lateral;
      w.angle[i] = patch.point.contact_angle;
    }
    creepages.push_back(w);
  }
  return creepages;
}

// The benchmark wheelset without lateral load at the balanced speed (22.6 m/s) through 50 m of
// straight, the 90 m transition of parameters/track-curve-R600-1km.json (clothoid and linear cant
// ramp to R 600 m with 0.13 m cant, d(cant)/ds = -0.96 mrad/m) and 60 m of the curve (interp
// model). The ramp's roll of the track frame is no slip (docs/track.md): a rigid wheelset's two
// wheels on their treads slip sideways alike, their lateral creepages differing by
// (|y'| / V + |yaw|) (cos g_L - cos g_R) and z' and roll' terms, below 1e-6 at contact angles below
// 0.1 rad and rates relative to the track of a quasi-static ramp. With the frame's roll rate p_t in
// the contact query each wheel got p_t y_c sin(g) / V more, whose difference between the wheels,
// |d(cant)/ds| 0.75 m (sin g_R - sin g_L), reached 5.4e-5 in the ramp. Bound 2e-6 (measured 1.7e-7).
// The ramp's largest lateral creepage, the angle of attack the yaw restraint allows (the steady
// curve's 6.0e-5) and the outward drift over the ramp (3.5 mm in 90 m, 3.9e-5): below 1e-4
// (measured 5.55e-5 on both wheels; with p_t in the query 7.8e-5 on the inner and 3.9e-5 on the
// outer wheel).
TEST(WheelsetInCurve, ACantRampAtTheBalancedSpeedAddsNoLateralCreepage) {
  static const std::shared_ptr<const ContactModel> model = make_contact_model("interp", test::s1002_uic60_geometry());
  const TrackSegment c = curve(400, 600, true, 0.13);
  RunSpec spec;
  spec.wheelset.lateral_force = 0.0;
  spec.wheelset.speed = TrackLayout::balanced_speed(c, 1.5, 9.81);
  ASSERT_NEAR(spec.wheelset.speed, 22.6, 0.1);
  spec.track = TrackLayout({straight(50), transition(90), c});
  spec.integrator.t_end = 200.0 / spec.wheelset.speed;
  spec.integrator.output_period = 2e-3;
  WheelsetSimulation sim(spec, std::make_shared<InProcessContact>(model), kR0);
  const std::vector<WheelsetSnapshot> out = run(sim);
  double difference = 0.0, largest = 0.0, angle = 0.0;
  int in_ramp = 0;
  for (const WheelCreepages& w : lateral_creepages(sim, *model, out)) {
    if (w.s <= 50.0 || w.s >= 140.0) continue;
    ++in_ramp;
    difference = std::max(difference, std::abs(w.lateral[0] - w.lateral[1]));
    largest = std::max({largest, std::abs(w.lateral[0]), std::abs(w.lateral[1])});
    angle = std::max({angle, std::abs(w.angle[0]), std::abs(w.angle[1])});
  }
  std::cout << "[ measured ] cant ramp at the balanced speed: largest |xi_y| " << largest
            << ", largest difference of the wheels' xi_y " << difference << ", largest contact angle " << angle
            << " rad\n";
  ASSERT_GT(in_ramp, 1000);
  EXPECT_LT(angle, 0.1);  // on the treads, where the bound of the difference holds
  EXPECT_LT(difference, 2e-6);
  EXPECT_LT(largest, 1e-4);
  EXPECT_GT(largest, 1e-5);  // the curve's angle of attack is there
}

// The contact query takes the rates relative to the track frame: a cant rate alone (the roll of a
// linear cant ramp, here the 1 km track's) changes none of its rates, while the curvature turns the
// yaw rate by V kappa and the speed to V (1 - kappa y). The gyroscopic moments keep the absolute
// rates: the yaw residual changes by I_yy Omega V d(cant)/ds.
TEST(WheelsetInCurve, ACantRateAloneLeavesTheContactQueryUnchanged) {
  const WheelsetParameters p;
  WheelsetEquations equations(p, kR0, kR0);
  const double y[kRigidUnknowns] = {-3e-3, 0.4601, 1e-3, 2e-4, 0.01, -0.002, 0.003, 1e-4, 65.0, 1.1, 0.9, 0.0, 0.0};
  const FollowedBranches branches;
  TrackPoint canted;
  canted.curvature = 1.0 / 600;
  canted.curvature_rate = 1.0 / 600 / 90;
  canted.cant_angle = -0.04;
  canted.cant_angle_rate = -std::asin(0.13 / 1.5) / 90;
  TrackPoint level = canted;
  level.cant_angle_rate = 0.0;
  equations.set_track(level);
  const ContactQuery a = equations.query(ContactFormulation::kRigid, y, branches);
  equations.set_track(canted);
  const ContactQuery b = equations.query(ContactFormulation::kRigid, y, branches);
  for (const ContactQuery* q : {&a, &b}) {
    EXPECT_EQ(q->y_dot, y[kUnknownYDot]);
    EXPECT_EQ(q->z_dot, y[kUnknownZDot]);
    EXPECT_EQ(q->roll_dot, y[kUnknownRollDot]);
    EXPECT_DOUBLE_EQ(q->yaw_dot, y[kUnknownYawDot] + p.speed / 600);
    EXPECT_DOUBLE_EQ(q->speed, p.speed * (1.0 + 3e-3 / 600));
    EXPECT_EQ(q->spin_rate, y[kUnknownSpinRate]);
    EXPECT_EQ(q->pose.y, y[kUnknownY]);
    EXPECT_EQ(q->pose.roll, y[kUnknownRoll]);
  }
  EXPECT_EQ(a.yaw_dot, b.yaw_dot);
  EXPECT_EQ(a.speed, b.speed);
  const double yp[kRigidUnknowns] = {};
  ContactResult contact;
  double r_level[kRigidUnknowns], r_canted[kRigidUnknowns];
  equations.set_track(level);
  equations.residual(ContactFormulation::kRigid, y, yp, contact, branches, r_level);
  equations.set_track(canted);
  equations.residual(ContactFormulation::kRigid, y, yp, contact, branches, r_canted);
  const double gyroscopic = p.spin_inertia * y[kUnknownSpinRate] * p.speed * canted.cant_angle_rate;
  EXPECT_NEAR(r_canted[kUnknownYawDot] - r_level[kUnknownYawDot], gyroscopic, 1e-9 * std::abs(gyroscopic));
  EXPECT_EQ(r_canted[kUnknownRollDot], r_level[kUnknownRollDot]);
}

}  // namespace
}  // namespace wrc
