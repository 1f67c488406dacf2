// The wheelset on a track layout (core/track, docs/track.md): the layout's curvature and cant
// along the distance (continuous through transitions, the signs of the conventions), its file
// (round trip, errors naming the file, segment and key), and the dynamics in curves: a free
// wheelset in a large-radius curve settles where it rolls purely, delta_r = 2 r0 e / R; at the
// balanced speed of a canted curve the wheelset stays on its treads and the lateral contact force
// balances only the suspension; a left-hand curve mirrors a right-hand one; straight track is the
// straight-track run bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

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
      {"t.json: segments[0]: radius: not a key of a straight"});
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
  // follow each run's own steps) in the rms to 1e-4 of the static wheel load (measured 1 N of
  // 87 kN).
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
// more than 0.5 % of the static wheel load (measured 114 N, 0.13 %; the outer wheel's force swings
// by 1 kN over the run). Without the frame's transport velocity in the contact (the centre's
// -p_t z) it jumped by 2.3 kN at each end of the ramp.
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
  EXPECT_GT(std::abs(angle_outer[1]), 0.2);  // the flange root
  EXPECT_LT(largest_step, 5e-3 * wheel_load);
  EXPECT_GT(swing, 2.0 * largest_step);
}

}  // namespace
}  // namespace wrc
