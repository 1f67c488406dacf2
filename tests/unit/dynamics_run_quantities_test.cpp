// SPDX-License-Identifier: Apache-2.0
// What a run reports of the wheel forces (docs/run-quantities.md): in the benchmark's quasi-steady
// state on straight track the axle's track-shift force balances the applied lateral load and the
// sum of Q the vertical load (less the suspension's shares); the summary's maxima are at least every
// output's value and say where they occurred; a bad flange angle is refused naming the value.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "run_to_end.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  ContactModelData data;
  if (model == "spline") data.splines = test::quick_spline_fit().model;
  return std::make_shared<InProcessContact>(make_contact_model(model, test::s1002_uic60_geometry(), {}, data));
}

// The benchmark (Fy = -20 kN towards the right rail, Fz + m g = 172.5 kN) to its quasi-steady
// state. Newton for the wheelset, inertia gone (|y''|, |z''| below 1e-3 m/s^2 there, i.e. < 2 N):
//   lateral:  sum of the rails' y forces + Fy + F_susp,y = 0, so sum Y = -(rails' y forces) = Fy + F_susp,y
//             with F_susp,y = -2 k_y y - 2 c_y y' (k_y = 0 in the benchmark, y' < 1e-6 m/s: < 0.04 N);
//   vertical: Q_L + Q_R = Fz + m g + 2 k_z (z - z_ref) + 2 c_z z'.
// Bound 0.05 N (2.5e-6 of Fy, 3e-7 of the load), for both models: what a quasi-steady state may
// still hold besides the terms written out, the inertia m y'' and m z'' of a state whose rates are
// below 1e-6 m/s (the damping terms, 2 c |y'| < 0.04 N, are included). Measured: 5e-9 N (one-point)
// and 1.6e-8 N (spline) lateral, 1.4e-9 / 2.4e-9 N vertical: Y and Q, summed from the patches, are
// the forces the equations balance.
TEST(RunQuantities, SteadyStateForcesBalanceTheLoads) {
  for (const std::string model : {"onepoint", "spline"}) {
    RunSpec spec;
    spec.integrator.t_end = 1.5;
    spec.integrator.output_period = 0.5;
    WheelsetSimulation sim(spec, contact(model), kR0);
    const WheelsetSnapshot s = test::run_to_end(sim).back();
    ASSERT_LT(std::abs(s.y_dot), 1e-6) << model << ": not quasi-steady";
    const WheelsetParameters& p = spec.wheelset;
    const PrimarySuspension& k = p.suspension;
    const double suspension_y = -2.0 * k.lateral_stiffness * s.y - 2.0 * k.lateral_damping * s.y_dot;
    const double sum_y = track_shift_force(s.wheels[0].lateral_force, s.wheels[1].lateral_force);
    EXPECT_NEAR(sum_y, p.lateral_force + suspension_y, 0.05) << model;
    const double suspension_z =
        2.0 * k.vertical_stiffness * (s.z - sim.equations().z_reference()) + 2.0 * k.vertical_damping * s.z_dot;
    const double sum_q = s.wheels[0].vertical_force + s.wheels[1].vertical_force;
    EXPECT_NEAR(sum_q, p.total_vertical_load() + suspension_z, 0.05) << model;
    // The right wheel carries the lateral load: its Y is positive (towards the track centre).
    EXPECT_GT(s.wheels[1].lateral_force, 0.0) << model;
    std::cout << "[ measured ] " << model << ": sum Y - Fy - suspension " << sum_y - p.lateral_force - suspension_y
              << " N, sum Q - load - suspension " << sum_q - p.total_vertical_load() - suspension_z << " N, Y/Q right "
              << s.wheels[1].y_over_q() << ", T gamma right " << s.wheels[1].wear_number << " N, p_max right "
              << s.wheels[1].max_pressure << " Pa\n";
  }
}

// The benchmark's first 0.6 s (the approach to the flange and the settling), an output every 1 ms.
RunSpec benchmark_start() {
  RunSpec spec;
  spec.integrator.t_end = 0.6;
  spec.integrator.output_period = 1e-3;
  return spec;
}

// The maxima cover every output sample (they also see every accepted step, so they may be larger),
// occur inside the run, at the distance speed * t, and the largest |Y/Q| of the benchmark is the
// right wheel's (the one pushed into its flange root).
TEST(RunQuantities, MaximaCoverTheOutputsAndSayWhere) {
  const RunSpec spec = benchmark_start();
  WheelsetSimulation sim(spec, contact("spline"), kR0);
  const std::vector<WheelsetSnapshot> out = test::run_to_end(sim);
  const RunExtremes& e = sim.extremes();
  double yq = 0.0, shift = 0.0, wear = 0.0, pressure = 0.0;
  for (const WheelsetSnapshot& s : out) {
    yq = std::max(yq, std::abs(s.wheels[1].y_over_q()));
    shift = std::max(shift, std::abs(track_shift_force(s.wheels[0].lateral_force, s.wheels[1].lateral_force)));
    wear = std::max(wear, s.wheels[1].wear_number);
    pressure = std::max(pressure, s.wheels[1].max_pressure);
  }
  EXPECT_GE(e.y_over_q[1].value, yq);
  EXPECT_GE(e.track_shift_force.value, shift);
  EXPECT_GE(e.wear_number[1].value, wear);
  EXPECT_GE(e.max_pressure[1].value, pressure);
  // Outputs are 1 ms apart and the contact data linear in between: the maxima lie close above them.
  EXPECT_LT(e.y_over_q[1].value, 1.05 * yq);
  EXPECT_GT(e.y_over_q[1].value, e.y_over_q[0].value);
  for (const RunMaximum* m : {&e.y_over_q[0], &e.y_over_q[1], &e.track_shift_force, &e.wear_number[1],
                              &e.max_pressure[1]}) {
    EXPECT_GE(m->t, 0.0);
    EXPECT_LE(m->t, spec.integrator.t_end);
    EXPECT_DOUBLE_EQ(m->distance, spec.wheelset.speed * m->t);
  }
  std::cout << "[ measured ] spline, 0.6 s: max |Y/Q| right " << e.y_over_q[1].value << " at t = " << e.y_over_q[1].t
            << " s, max |sum Y| " << e.track_shift_force.value << " N at t = " << e.track_shift_force.t
            << " s, max T gamma right " << e.wear_number[1].value << " N, max p right " << e.max_pressure[1].value
            << " Pa\n";
}

// EN 14363's 2 m sliding means of sum Y and Y/Q, taken by the run over its accepted steps, against
// the same means computed here by the trapezoid rule from the 1 ms output samples (the outputs lie
// on the steps' linear interpolant, so the two differ only where a 1 ms sample cuts a kink: bound
// 0.5 %): the largest |mean| agrees, lies below the instantaneous maximum, and is reported at a
// window's end, a multiple of 0.5 m, at t = distance / speed.
TEST(RunQuantities, SlidingMeansOverTwoMetresAgreeWithTheOutputs) {
  const RunSpec spec = benchmark_start();
  WheelsetSimulation sim(spec, contact("spline"), kR0);
  const std::vector<WheelsetSnapshot> out = test::run_to_end(sim);
  const RunExtremes& e = sim.extremes();
  const double v = spec.wheelset.speed;
  const auto sum_y = [](const WheelsetSnapshot& s) {
    return track_shift_force(s.wheels[0].lateral_force, s.wheels[1].lateral_force);
  };
  const auto y_over_q_right = [](const WheelsetSnapshot& s) { return s.wheels[1].y_over_q(); };
  const auto largest_mean = [&](auto quantity) {
    double largest = 0.0;
    for (double end = 2.0; end <= v * out.back().t; end += 0.5) {
      double integral = 0.0;
      for (size_t k = 1; k < out.size(); ++k) {
        const double a = v * out[k - 1].t, b = v * out[k].t;
        const double lo = std::max(a, end - 2.0), hi = std::min(b, end);
        if (!(hi > lo)) continue;
        const double fa = quantity(out[k - 1]), fb = quantity(out[k]);
        const auto f = [&](double x) { return fa + (fb - fa) * (x - a) / (b - a); };
        integral += 0.5 * (hi - lo) * (f(lo) + f(hi));
      }
      largest = std::max(largest, std::abs(integral / 2.0));
    }
    return largest;
  };
  ASSERT_GT(v * spec.integrator.t_end, 10.0);
  EXPECT_NEAR(e.track_shift_force_2m.value, largest_mean(sum_y), 5e-3 * e.track_shift_force_2m.value);
  EXPECT_NEAR(e.y_over_q_2m[1].value, largest_mean(y_over_q_right), 5e-3 * e.y_over_q_2m[1].value);
  EXPECT_LE(e.track_shift_force_2m.value, e.track_shift_force.value);
  EXPECT_LE(e.y_over_q_2m[1].value, e.y_over_q[1].value);
  for (const RunMaximum* m : {&e.y_over_q_2m[0], &e.y_over_q_2m[1], &e.track_shift_force_2m}) {
    EXPECT_DOUBLE_EQ(std::fmod(m->distance, 0.5), 0.0) << m->distance;
    EXPECT_GE(m->distance, 2.0);
    EXPECT_NEAR(m->t, m->distance / v, 1e-12);
  }
  std::cout << "[ measured ] spline, 0.6 s: (sum Y) 2 m " << e.track_shift_force_2m.value << " N at "
            << e.track_shift_force_2m.distance << " m (instantaneous " << e.track_shift_force.value
            << " N), (Y/Q) 2 m right " << e.y_over_q_2m[1].value << " (instantaneous " << e.y_over_q[1].value << ")\n";
}

TEST(RunQuantities, BadFlangeAngleIsRefusedNamingIt) {
  for (const double bad : {0.0, -0.2, 1.5707963267948966, 2.0}) {
    RunSpec spec;
    spec.wheelset.flange_angle = bad;
    try {
      spec.validate();
      ADD_FAILURE() << "flange_angle " << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("flange_angle"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("outside (0, 1.57"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace wrc
