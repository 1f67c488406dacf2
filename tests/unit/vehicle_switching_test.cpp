// SPDX-License-Identifier: Apache-2.0
// Contact-point switches per wheelset in a vehicle run (VehicleSimulation, rigid one-point contact
// on S1002/UIC60, in-process): the vehicle file of one wheelset switches where the lone wheelset's
// run switches (its switching is validated in dynamics_onepoint_test.cpp against the exact
// geometry), and every wheel of a bogie follows the lowest minimum of the exact distance function
// at every accepted step while its wheelsets cross S1002's contact-point jumps.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "coach_on_track.hpp"
#include "core/spline/spline_geometry_fit.hpp"
#include "single_wheelset_vehicle_run.hpp"

namespace wrc {
namespace {

using test::s1002_uic60;

std::shared_ptr<ContactEvaluator> onepoint(double r0) { return test::s1002_contact("onepoint", r0); }

// The benchmark's wheelset without its lateral load, at 50 m/s, released 5 mm off the centre
// line: its left wheel's point jumps twice on the way to the centre (from the flange to the
// flange root at 1.5 ms, from the flange root to the tread at 0.19 s), then its motion decays.
constexpr double kY0 = 5e-3;
constexpr double kTEnd = 1.0;
constexpr double kR0 = 0.46;
constexpr double kSpeed = 50.0;

// The file of one wheelset and the lone wheelset's run, started from the same state (the vehicle
// rests with its wheelset held at y0, the spin where its creep torques balance; the lone run from
// y0 with that spin): the same equations (VehicleLinearStability's test: the same eigenvalues)
// integrated with the same tolerances, so the same switches at the same times. What differs is
// the Newton matrix (the vehicle's forward differences of the whole residual, rebuilt when cj
// changes by 25 %; the wheelset's own, at every change), so the corrector's iterates, within the integrator's tolerances: rtol 1e-6 of y (5 mm) is 5 nm a
// step, some tens of nm over the run's steps (measured: 5e-8 m, and 1.5e-6 s between the switch
// times). Tolerances 5e-7 m of y over the run, 1e-5 s per switch time; a lost switch, or a
// restart from inconsistent values (a velocity not projected, a wrong normal force), moves the
// run by micrometres within milliseconds.
TEST(VehicleSwitching, TheSingleWheelsetFileSwitchesAsTheLoneWheelset) {
  const VehicleRunSpec spec = test::single_wheelset_run(kSpeed, kY0, kTEnd);
  VehicleSimulation vehicle(spec, onepoint(kR0), kR0);
  std::vector<WheelsetSnapshot> vehicle_out;
  vehicle.on_output([&](const VehicleSnapshot& s) { vehicle_out.push_back(vehicle.wheelset_snapshot(s, 0)); });
  vehicle.start();
  ASSERT_FALSE(vehicle_out.empty());
  const RunSpec lone = test::lone_run_of(spec, vehicle_out.front().spin_rate);
  vehicle.run();
  ASSERT_EQ(vehicle.state(), RunState::kFinished) << vehicle.message();

  WheelsetSimulation wheelset(lone, onepoint(kR0), kR0);
  std::vector<WheelsetSnapshot> lone_out;
  wheelset.on_output([&](const WheelsetSnapshot& s) { lone_out.push_back(s); });
  wheelset.run();
  ASSERT_EQ(wheelset.state(), RunState::kFinished) << wheelset.message();

  const std::vector<SwitchRecord>& a = vehicle.switches();
  const std::vector<SwitchRecord>& b = wheelset.switches();
  ASSERT_GE(b.size(), 2u) << "the lone run should cross a jump both ways";
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    SCOPED_TRACE("switch " + std::to_string(i));
    EXPECT_EQ(a[i].wheelset, 0);
    EXPECT_EQ(a[i].wheel, b[i].wheel);
    EXPECT_NEAR(a[i].t, b[i].t, 1e-5);
    EXPECT_NEAR(a[i].s_to, b[i].s_to, 1e-6);
  }
  ASSERT_EQ(vehicle_out.size(), lone_out.size());
  double worst = 0.0;
  for (size_t k = 0; k < lone_out.size(); ++k) worst = std::max(worst, std::abs(vehicle_out[k].y - lone_out[k].y));
  EXPECT_LT(worst, 5e-7);
  const RunCounters c = vehicle.counters();
  EXPECT_EQ(c.contact_switches, static_cast<long>(a.size()));
  EXPECT_EQ(c.restarts, wheelset.counters().restarts);
  std::cout << "[ measured ] " << a.size() << " switches, largest |y difference| " << worst << " m, largest switch "
            << "time difference " << [&] {
                 double d = 0.0;
                 for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i].t - b[i].t));
                 return d;
               }() << " s\n";
}

// The lowest minimum of wheel `wheel`'s exact distance function at the wheelset's pose, and how
// far the point at s_followed [m] lies above it [m] (infinity when s_followed is no minimum).
double excess_over_lowest(const WheelsetGeometry& geometry, const WheelsetSnapshot& s, int wheel, double s_followed) {
  WheelsetPose pose;
  pose.y = s.y;
  pose.z = s.z;
  pose.roll = s.roll;
  pose.yaw = s.yaw;
  double lowest = std::numeric_limits<double>::infinity();
  double followed = std::numeric_limits<double>::infinity();
  for (const ContactPoint& p : geometry.potential_points(static_cast<WheelSide>(wheel), pose, PotentialPointSearch{})) {
    if (!p.is_minimum) continue;
    lowest = std::min(lowest, p.distance);
    if (std::abs(p.s - s_followed) < 1e-9) followed = p.distance;
  }
  return followed - lowest;
}

// The Cooperrider bogie on S1002/UIC60 (r0 0.425 m, friction 0.15) at 60 m/s, its leading
// wheelset released 1 mm off the centre: both wheelsets oscillate about the contact-point jumps
// near the centre. After every accepted step each of the 4 wheels follows a minimum of the exact
// distance function (a scan of the geometry of its own, not the model's event function) at most
// kBranchTolerance = 1e-9 m above the lowest; before per-wheelset switching a run stepped through
// the jumps, a discontinuity of the contact forces, and at 100 m/s met a corrector iterate of 1.4e8
// N. The switches are located as events, each wheelset's its own.
TEST(VehicleSwitching, EveryWheelOfTheBogieFollowsTheLowestMinimum) {
  constexpr double r0 = 0.425;
  const VehicleRunSpec spec = test::cooperrider_bogie_run(60.0, 1e-3, 1.0);
  const std::shared_ptr<const WheelsetGeometry> geometry = s1002_uic60(r0);
  VehicleSimulation sim(spec, std::make_shared<InProcessContact>(make_contact_model("onepoint", geometry)), r0);
  sim.start();
  double worst = 0.0;
  long checked = 0;
  while (sim.advance()) {
    const VehicleSnapshot s = sim.snapshot();
    for (size_t w = 0; w < 2; ++w) {
      const WheelsetSnapshot ws = sim.wheelset_snapshot(s, w);
      for (int i = 0; i < 2; ++i) {
        const double excess = excess_over_lowest(*geometry, ws, i, sim.last_step_wheels(w)[static_cast<size_t>(i)].s_wheel);
        ASSERT_LE(excess, kBranchTolerance) << "wheelset " << w << " wheel " << i << " at t = " << s.t;
        worst = std::max(worst, excess);
        ++checked;
      }
    }
  }
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  const RunCounters c = sim.counters();
  EXPECT_GE(c.contact_switches, 8);
  EXPECT_EQ(c.missed_switches, 0);
  EXPECT_LE(c.max_branch_excess, kBranchTolerance);
  bool leading = false, trailing = false;
  for (const SwitchRecord& r : sim.switches()) (r.wheelset == 0 ? leading : trailing) = true;
  EXPECT_TRUE(leading && trailing) << "each wheelset crosses the jumps";
  std::cout << "[ measured ] " << checked << " wheel checks, " << c.contact_switches << " switches, " << c.steps
            << " steps, largest excess " << worst << " m\n";
}

// The spline model fitted over flange contact as the vehicle benchmark fits it (y within +-12 mm,
// roll +-4 mrad, yaw +-5 mrad, 20 x 4 x 2 knot intervals) runs the coach through the place where
// a wheel's fitted flange clearance falls below 0 while the exact geometry has no flange-side
// minimum (t = 6.88 s at a track run's tolerances): before the tread kept its contact there, the
// wheel switched to flange contact and back without end and the run stopped ("finds no branch
// that is the lowest after 8 switches"). To 7.5 s, every wheel loaded at the end.
TEST(VehicleSwitching, TheSplineModelFittedOverFlangeContactRunsThroughTheFitsBand) {
  VehicleRunSpec spec = test::coach_on_irregular_track(1);
  spec.run.integrator.t_end = 7.5;
  spec.run.integrator.relative_tolerance = 1e-4;
  spec.run.integrator.position_tolerance = 1e-6;
  spec.run.integrator.velocity_tolerance = 1e-4;
  spec.run.integrator.output_period = 0.01;
  SplineFitOptions o;
  o.y_min = -0.012;
  o.y_max = 0.012;
  o.roll_max = 0.004;
  o.yaw_max = 0.005;
  o.intervals = {20, 4, 2};
  const auto geometry = test::s1002_uic60_geometry();
  const SplineFit fit = fit_spline_geometry(*geometry, o);
  VehicleSimulation sim(spec,
                        std::make_shared<InProcessContact>(make_contact_model("spline", geometry, {}, ContactModelData{fit.model})),
                        0.46);
  sim.start();
  sim.run();
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  for (size_t w = 0; w < 4; ++w)
    for (const WheelOutput& wheel : sim.last_step_wheels(w)) EXPECT_GT(wheel.normal_force, 0.0) << "wheelset " << w;
}

}  // namespace
}  // namespace wrc
