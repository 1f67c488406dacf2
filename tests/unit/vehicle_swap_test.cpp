// SPDX-License-Identifier: Apache-2.0
// Model swaps of a vehicle run (VehicleSimulation::schedule_swap, request_swap): every wheelset's
// model changes at a step boundary, each wheelset's state made one of the new formulation as the
// lone wheelset's swap makes it (validated in dynamics_swap_test.cpp), the vehicle restarted from
// consistent values. Against the lone wheelset's swaps on the vehicle file of one wheelset, and
// on the Cooperrider bogie: rigid to elastic and back, every wheelset, the run going on.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include "single_wheelset_vehicle_run.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;

// The benchmark's wheelset without its lateral load at 50 m/s, released 5 mm off the centre, with
// one-point contact swapped to multipoint (elastic) at 0.3 s and back at 0.6 s: the file of one
// wheelset on the vehicle's equations and the lone wheelset's run from the same state make the
// same swaps (each at the first step boundary after its time: within max_step, 0.01 s, of each
// other) and end in the same state. Each swap moves the state onto the other contact (the elastic wheelset sinks by its
// Hertz approach, about 0.1 mm; back in rigid contact it is projected up again), the same
// computation in both (adapt_to_formulation); what differs is the Newton matrix's policy (the
// vehicle's rebuilt when cj changes by 25 %), so the steps and the swaps' step boundaries (3 ms
// apart measured), within the integrator's tolerances: measured 2.8e-7 m of y between the runs'
// outputs, tolerance 1e-6 m. A swap restarted from a state
// not moved onto the new contact (an elastic wheelset at zero approach, a rigid one sunk into its
// rails) fails at once or ends far from the lone run's.
TEST(VehicleSwap, TheSingleWheelsetFileSwapsAsTheLoneWheelset) {
  const VehicleRunSpec spec = test::single_wheelset_run(50.0, 5e-3, 1.0);
  VehicleSimulation vehicle(spec, test::s1002_contact("onepoint", kR0), kR0);
  vehicle.schedule_swap(0.3, test::s1002_contact("multipoint", kR0));
  vehicle.schedule_swap(0.6, test::s1002_contact("onepoint", kR0));
  std::vector<WheelsetSnapshot> vehicle_out;
  vehicle.on_output([&](const VehicleSnapshot& s) { vehicle_out.push_back(vehicle.wheelset_snapshot(s, 0)); });
  vehicle.start();
  ASSERT_FALSE(vehicle_out.empty());
  WheelsetSimulation wheelset(test::lone_run_of(spec, vehicle_out.front().spin_rate),
                              test::s1002_contact("onepoint", kR0), kR0);
  wheelset.schedule_swap(0.3, test::s1002_contact("multipoint", kR0));
  wheelset.schedule_swap(0.6, test::s1002_contact("onepoint", kR0));
  std::vector<WheelsetSnapshot> lone_out;
  wheelset.on_output([&](const WheelsetSnapshot& s) { lone_out.push_back(s); });
  vehicle.run();
  wheelset.run();
  ASSERT_EQ(vehicle.state(), RunState::kFinished) << vehicle.message();
  ASSERT_EQ(wheelset.state(), RunState::kFinished) << wheelset.message();
  ASSERT_EQ(vehicle.swaps().size(), 2u) << vehicle.message();
  ASSERT_EQ(wheelset.swaps().size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(vehicle.swaps()[i].from, wheelset.swaps()[i].from);
    EXPECT_EQ(vehicle.swaps()[i].to, wheelset.swaps()[i].to);
    EXPECT_NEAR(vehicle.swaps()[i].t, wheelset.swaps()[i].t, 1e-2);
  }
  EXPECT_EQ(vehicle.model(), "onepoint");
  ASSERT_EQ(vehicle_out.size(), lone_out.size());
  double worst = 0.0;
  for (size_t k = 0; k < lone_out.size(); ++k) {
    worst = std::max(worst, std::abs(vehicle_out[k].y - lone_out[k].y));
    const double t = lone_out[k].t;
    if ((t > 0.31 && t < 0.6) || t > 0.61 || t < 0.3) {
      EXPECT_EQ(vehicle_out[k].model, lone_out[k].model) << "at t = " << t;
    }
  }
  EXPECT_LT(worst, 1e-6);
  std::cout << "[ measured ] swaps at " << vehicle.swaps()[0].t << " and " << vehicle.swaps()[1].t << " s (lone "
            << wheelset.swaps()[0].t << ", " << wheelset.swaps()[1].t << "), largest |y difference| " << worst
            << " m\n";
}

// The Cooperrider bogie on S1002/UIC60 at 60 m/s, its leading wheelset released 1 mm off the
// centre, swapped from one-point to multipoint contact at 0.2 s and back at 0.4 s: both wheelsets
// change model (every output after a swap names the new one), every wheel stays loaded, and each
// wheelset's wheels carry its share of the weight: in the rigid phases their sum is twice the
// static wheel load to 1 %, in the elastic phase on average over its outputs to 1 % (the
// wheelset's vertical mode on the Hertz springs, some 200 Hz, is undamped in this bogie without
// primary dampers: its loads swing by +-15 % in a multipoint run from the start too, so the
// average is the measure there). A swap that dropped or doubled a wheelset's load, or lost its
// contact, misses by tens of percent; the run reaches its end.
TEST(VehicleSwap, EveryWheelsetOfTheBogieChangesModel) {
  constexpr double r0 = 0.425;
  const VehicleRunSpec spec = test::cooperrider_bogie_run(60.0, 1e-3, 0.6);
  VehicleSimulation sim(spec, test::s1002_contact("onepoint", r0), r0);
  sim.schedule_swap(0.2, test::s1002_contact("multipoint", r0));
  sim.schedule_swap(0.4, test::s1002_contact("onepoint", r0));
  const double load = sim.wheel_loads()[0];
  std::array<double, 2> elastic_sum{0.0, 0.0};
  long elastic_samples = 0;
  long checked = 0;
  sim.on_output([&](const VehicleSnapshot& s) {
    const bool rigid = s.t < 0.2 || s.t > 0.41;
    const bool elastic = s.t > 0.21 && s.t < 0.4;
    if (elastic) ++elastic_samples;
    for (size_t w = 0; w < 2; ++w) {
      const WheelsetSnapshot ws = sim.wheelset_snapshot(s, w);
      if (rigid || elastic) {
        EXPECT_EQ(ws.model, rigid ? "onepoint" : "multipoint") << "wheelset " << w << " at t = " << s.t;
      }
      const double sum = ws.wheels[0].normal_force + ws.wheels[1].normal_force;
      for (const WheelOutput& wheel : ws.wheels) EXPECT_GT(wheel.normal_force, 0.0) << "wheelset " << w << " at t = " << s.t;
      if (rigid) {
        EXPECT_NEAR(sum, 2.0 * load, 0.01 * 2.0 * load) << "wheelset " << w << " at t = " << s.t;
      }
      if (elastic) elastic_sum[w] += sum;
      ++checked;
    }
  });
  sim.run();
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  ASSERT_EQ(sim.swaps().size(), 2u) << sim.message();
  EXPECT_EQ(sim.swaps()[0].to, "multipoint");
  EXPECT_EQ(sim.swaps()[1].to, "onepoint");
  EXPECT_GE(sim.counters().restarts, 2);
  EXPECT_GT(checked, 1000);
  ASSERT_GT(elastic_samples, 100);
  for (size_t w = 0; w < 2; ++w)
    EXPECT_NEAR(elastic_sum[w] / static_cast<double>(elastic_samples), 2.0 * load, 0.01 * 2.0 * load) << "wheelset " << w;
  std::cout << "[ measured ] elastic phase: mean wheelset loads " << elastic_sum[0] / static_cast<double>(elastic_samples)
            << " and " << elastic_sum[1] / static_cast<double>(elastic_samples) << " N against " << 2.0 * load << " N\n";
}

}  // namespace
}  // namespace wrc
