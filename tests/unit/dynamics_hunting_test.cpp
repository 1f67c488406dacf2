// SPDX-License-Identifier: Apache-2.0
// Hunting runs and the ramp-down continuation (core/dynamics/hunting_run.hpp,
// hunting_continuation.hpp, docs/bifurcation.md).
//
// 1. Small oscillations agree with the linearisation: the benchmark wheelset with soft yaw springs
//    (k_x = 1e6 N/m per box), S1002 on UIC60, elastic contact (multipoint), started 0.01 mm off
//    centre, at 32 and 42 m/s, on both sides of the linear critical speed (37.5 m/s for this model,
//    docs/stability.md). The run's growth per cycle is exp(Re lambda T) and its frequency
//    Im lambda / 2 pi of the least damped eigenvalue of LinearStability at the same speed: two
//    independent computations (time integration against the eigenvalues of the linearised
//    residual). Measured: frequencies within 0.03 % (32 m/s) and 0.1 % (42 m/s), growth rates
//    f ln(growth) within 0.008 and 0.0001 1/s. Asked: 0.5 % and 0.03 1/s. What is left is the
//    amplitude's nonlinearity (S1002's effective conicity changes with amplitude, what makes the
//    bifurcation subcritical), while a factor 2 error in a creep force moves Re lambda by 0.5 1/s
//    or more.
// 2. The Hopf bifurcation is subcritical: at 55 m/s, below the rigid one-point model's linear
//    critical speed (59.24 m/s), a 0.05 mm start decays and a 0.5 mm start grows. Between them
//    lies an unstable cycle, so a hunting cycle exists below the linear critical speed. A
//    supercritical bifurcation would let both decay. (The 0.5 mm run reaches the flange and lifts
//    a wheel at 1.4 s, where the rigid formulation stops; 1 s is judged.)
// 3. The continuation's logic on a runner whose answer is set (no simulation): the ramp-down
//    carries each run's end state to the next speed, stops at the first collapse, and the
//    bisection brackets the set critical speed to the tolerance.
// 4. Every contact model decays at 5 m/s with soft yaw springs (below).

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "core/dynamics/hunting_continuation.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/models/contact_model_factory.hpp"
#include "expect_invalid.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  return std::make_shared<InProcessContact>(make_contact_model(model, test::s1002_uic60_geometry()));
}

RunSpec soft_yaw() {
  RunSpec spec;
  spec.wheelset.lateral_force = 0.0;
  spec.wheelset.suspension.longitudinal_stiffness = 1e6;
  return spec;
}

TEST(Hunting, SmallOscillationsFollowTheLinearisation) {
  const auto c = contact("multipoint");
  const RunSpec spec = soft_yaw();
  LinearStability stability(spec.wheelset, c, kR0);
  HuntingSettings settings;
  settings.settle_time = settings.window = settings.max_time = 2.0;
  settings.centred_amplitude = 1e-9;  // measure the decay, do not stop at "centred"
  for (double v : {32.0, 42.0}) {
    const StabilityMode mode = stability.linearise(v).least_damped();
    const HuntingRun r = run_hunting(spec, v, InitialState{1e-5, 0, 0, 0, 0}, c, kR0, settings);
    ASSERT_NE(r.state, HuntingState::kFailed) << r.message;
    ASSERT_GE(r.cycle.cycles, 4) << v;
    const double sigma = r.cycle.frequency() * std::log(r.cycle.growth);
    EXPECT_NEAR(r.cycle.frequency(), mode.frequency(), 0.005 * mode.frequency()) << v;
    EXPECT_NEAR(sigma, mode.eigenvalue.real(), 0.03) << v;
    EXPECT_EQ(r.state, v < 37.5 ? HuntingState::kDecaying : HuntingState::kGrowing) << v;
    std::cout << "[ measured ] " << v << " m/s: frequency " << r.cycle.frequency() << " Hz (linear " << mode.frequency()
              << "), growth rate " << sigma << " 1/s (linear " << mode.eigenvalue.real() << ")\n";
    EXPECT_FALSE(r.flange_contact) << v;
  }
}

TEST(Hunting, SubcriticalBelowTheLinearCriticalSpeed) {
  const auto c = contact("onepoint");
  const RunSpec spec = soft_yaw();
  HuntingSettings settings;
  settings.settle_time = settings.window = settings.max_time = 1.0;
  const HuntingRun small = run_hunting(spec, 55.0, InitialState{5e-5, 0, 0, 0, 0}, c, kR0, settings);
  const HuntingRun large = run_hunting(spec, 55.0, InitialState{5e-4, 0, 0, 0, 0}, c, kR0, settings);
  EXPECT_TRUE(small.state == HuntingState::kDecaying || small.state == HuntingState::kCentred)
      << hunting_state_name(small.state) << " growth " << small.cycle.growth;
  EXPECT_LT(small.cycle.growth, 0.99);
  ASSERT_EQ(large.state, HuntingState::kGrowing) << large.message << " growth " << large.cycle.growth;
  EXPECT_GT(large.cycle.growth, 1.01);
}

// 4. The four contact models agree in kind at low speed: the soft-yaw wheelset at 5 m/s from
//    0.4 mm, where the exact models decay (growth about 0.5 per cycle at 0.44 Hz) and the
//    spline model with a y blend across S1002's centred jump kept a 0.3 mm cycle (docs/
//    bifurcation.md). Every model must be within 0.01 mm of centre (the settings' centred
//    amplitude) within 20 s, still losing more than 10 % per cycle (measured: onepoint 0.0015 mm,
//    growth 0.50; interp 0.0016, 0.50; multipoint 0.0005, 0.61; spline 0.0020, 0.51): a cycle of
//    the fit's making fails it by a factor of 30.
TEST(Hunting, EveryModelDecaysAtFiveMetresPerSecondWithSoftYawSprings) {
  HuntingSettings settings;
  settings.max_time = 20.0;
  ASSERT_EQ(settings.centred_amplitude, 1e-5);
  for (const char* model : {"onepoint", "interp", "multipoint", "spline"}) {
    const auto c = std::make_shared<InProcessContact>(make_contact_model(
        model, test::s1002_uic60_geometry(), ContactModelOptions{}, ContactModelData{test::default_spline_fit().model}));
    const HuntingRun r = run_hunting(soft_yaw(), 5.0, InitialState{4e-4, 0, 0, 0, 0}, c, kR0, settings);
    std::cout << "[ measured ] " << model << " at 5 m/s: " << hunting_state_name(r.state) << " after "
              << r.simulated_time << " s, amplitude " << r.cycle.amplitude << " m, growth " << r.cycle.growth
              << ", " << r.cycle.frequency() << " Hz\n";
    ASSERT_NE(r.state, HuntingState::kFailed) << model << ": " << r.message;
    EXPECT_FALSE(r.persists()) << model << ": " << hunting_state_name(r.state) << ", amplitude " << r.cycle.amplitude;
    EXPECT_TRUE(r.state == HuntingState::kCentred || r.state == HuntingState::kDecaying)
        << model << ": " << hunting_state_name(r.state);
    EXPECT_LT(r.cycle.amplitude, 1e-5) << model << " after " << r.simulated_time << " s";
    EXPECT_LT(r.cycle.growth, 0.9) << model;  // decaying by more than 10 % per cycle, not hovering
  }
}

// A runner whose cycle persists at and above kCritical from any start off centre; its end state
// records the speed it ran at, so the test sees where each run started.
constexpr double kCritical = 42.3;

HuntingRun fake_run(double speed, const InitialState& start) {
  HuntingRun r;
  r.speed = speed;
  r.start = start;
  r.state = speed >= kCritical && start.y != 0 ? HuntingState::kLimitCycle : HuntingState::kCentred;
  r.cycle.amplitude = r.state == HuntingState::kLimitCycle ? 6e-3 : 0.0;
  r.end.y = r.state == HuntingState::kLimitCycle ? speed * 1e-4 : 0.0;  // marks the speed
  return r;
}

TEST(Hunting, ContinuationBracketsTheCollapse) {
  ContinuationSettings settings;
  settings.speed_tolerance = 0.1;
  const std::vector<double> speeds{30, 35, 40, 45, 50, 55, 60};
  const HuntingDiagram d = trace_hunting(speeds, fake_run, settings);
  ASSERT_EQ(d.centred.size(), speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) EXPECT_EQ(d.centred[i].start.y, settings.small_disturbance.y);
  // Down from 60: 60, 55, 50, 45 persist, 40 collapses.
  ASSERT_EQ(d.ramp_down.size(), 5u);
  EXPECT_EQ(d.ramp_down.front().start.y, settings.large_disturbance.y);
  for (std::size_t i = 1; i < d.ramp_down.size(); ++i)
    EXPECT_DOUBLE_EQ(d.ramp_down[i].start.y, d.ramp_down[i - 1].speed * 1e-4) << i;  // the previous run's end
  EXPECT_EQ(d.ramp_down.back().speed, 40.0);
  ASSERT_TRUE(d.critical.found);
  EXPECT_GE(d.critical.speed, kCritical);
  EXPECT_LE(d.critical.collapsed_at, kCritical);
  EXPECT_LE(d.critical.speed - d.critical.collapsed_at, settings.speed_tolerance);
  EXPECT_EQ(d.refinement.size(), 6u);  // 5 m/s halved to below 0.1 m/s: 5 / 2^6 = 0.078
}

TEST(Hunting, NoCollapseNoCriticalSpeed) {
  ContinuationSettings settings;
  // Every speed above the set critical one: the cycle persists down to the lowest.
  const HuntingDiagram d = trace_hunting({50, 55, 60}, fake_run, settings);
  EXPECT_EQ(d.ramp_down.size(), 3u);
  EXPECT_FALSE(d.critical.found);
  EXPECT_TRUE(d.refinement.empty());
}

TEST(Hunting, PersistingAmplitude) {
  // The set runner's cycles are 6 mm: asked for 7 mm, none persists, not even at the top speed.
  ContinuationSettings settings;
  settings.persisting_amplitude = 7e-3;
  const HuntingDiagram d = trace_hunting({50, 55, 60}, fake_run, settings);
  ASSERT_EQ(d.ramp_down.size(), 1u);
  EXPECT_FALSE(d.critical.found);
  settings.persisting_amplitude = 5e-3;
  EXPECT_EQ(trace_hunting({30, 35, 40, 45, 50, 55, 60}, fake_run, settings).critical.speed,
            trace_hunting({30, 35, 40, 45, 50, 55, 60}, fake_run, ContinuationSettings{}).critical.speed);
}

TEST(Hunting, UnstableCycleBracketsTheSeparatrix) {
  // Starts above 1.7 mm grow, below decay: 6 halvings of [0.05, 6] mm bracket 1.7 mm within 0.093 mm.
  auto separatrix = [](double speed, const InitialState& start) {
    HuntingRun r;
    r.speed = speed;
    r.start = start;
    r.state = HuntingState::kDecaying;
    r.cycle.cycles = 3;
    r.cycle.amplitude = start.y;
    r.cycle.growth = start.y > 1.7e-3 ? 1.1 : 0.9;
    return r;
  };
  const UnstableCycle u = unstable_cycle(separatrix, 45.0, 5e-5, 6e-3, 6);
  EXPECT_EQ(u.runs, 6);
  EXPECT_LE(u.decaying_start, 1.7e-3);
  EXPECT_GT(u.growing_start, 1.7e-3);
  EXPECT_NEAR(u.growing_start - u.decaying_start, (6e-3 - 5e-5) / 64, 1e-12);
  EXPECT_EQ(u.run.start.y, u.decaying_start);
  test::expect_invalid([&] { unstable_cycle(separatrix, 45.0, 6e-3, 5e-5, 6); }, "must be above");
}

TEST(Hunting, Errors) {
  ContinuationSettings settings;
  test::expect_invalid([&] { trace_hunting({50}, fake_run, settings); }, "1 speeds, need at least 2");
  test::expect_invalid([&] { trace_hunting({50, 40}, fake_run, settings); }, "not ascending at 40");
  settings.run.window = 3.0;
  test::expect_invalid([&] { trace_hunting({40, 50}, fake_run, settings); }, "window");
  settings = {};
  settings.speed_tolerance = 0;
  test::expect_invalid([&] { trace_hunting({40, 50}, fake_run, settings); }, "speed_tolerance");
  test::expect_invalid([&] { run_hunting(soft_yaw(), -1.0, {}, contact("onepoint"), kR0, {}); }, "speed = -1");
}

}  // namespace
}  // namespace wrc
