// SPDX-License-Identifier: Apache-2.0
// The swap between the rigid and the elastic formulation in both directions, the one
// WheelsetDynamics.SwapBetweenRigidAndElasticIsConsistent (dynamics_wheelset_test.cpp) leaves out
// included: rigid (interp) -> elastic (multipoint) -> rigid (interp) in one run, and a run that
// starts elastic (multipoint) swapped to rigid (interp). At each swap the formulation changes, the swap is
// listed, the normal forces go on continuously and the run finishes.
//
// Tolerances. The benchmark's wheelset is in quasi-steady rolling at the swap times,
// so the load each wheel carries is the same in both formulations up to the small motion of one
// output period (1 ms): the elastic one is settled to the rigid normal forces (settle_elastic), the
// rigid one starts from the elastic forces and is projected onto its constraints. 2 % of the
// wheel's load is the bound of the existing rigid -> elastic test, kept for both directions; a
// swap that lost the normal forces (rigid ones restarted from 0) or took the wrong wheel's would
// be off by 100 % or by the two wheels' difference (25 % under the benchmark's lateral load).
// Rigid contact after the swap back: the gap of each wheel at the end is 0 to the rigid
// formulation's position tolerance (the projected constraint, 1e-9 m with margin).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  static const std::shared_ptr<const ContactModel> interp = make_contact_model("interp", test::s1002_uic60_geometry());
  if (model == "interp") return std::make_shared<InProcessContact>(interp);
  return std::make_shared<InProcessContact>(make_contact_model(model, test::s1002_uic60_geometry()));
}

RunSpec short_benchmark(double t_end) {
  RunSpec spec;
  spec.integrator.t_end = t_end;
  spec.integrator.output_period = 1e-3;
  return spec;
}

// At the swap from `from` to `to` in outputs (the last output with `from` and the first with `to`,
// one output period apart): both wheels' normal forces within 2 % of the earlier ones.
void expect_continuous_normal_forces(const std::vector<WheelsetSnapshot>& out, const std::string& from,
                                     const std::string& to, double after) {
  for (size_t k = 1; k < out.size(); ++k) {
    if (out[k].t <= after || out[k - 1].model != from || out[k].model != to) continue;
    for (int i = 0; i < 2; ++i) {
      const double before = out[k - 1].wheels[i].normal_force, now = out[k].wheels[i].normal_force;
      ASSERT_GT(before, 1e4) << from << " -> " << to << ", wheel " << i;  // both wheels carry load
      EXPECT_NEAR(now, before, 0.02 * before) << from << " -> " << to << " at t = " << out[k].t << ", wheel " << i;
      std::cout << "[ measured ] " << from << " -> " << to << " wheel " << i << ": " << before << " N -> " << now
                << " N (" << 100.0 * (now - before) / before << " %)\n";
    }
    return;
  }
  ADD_FAILURE() << "no output pair " << from << " -> " << to << " after t = " << after;
}

// Rigid -> elastic at 0.1 s (scheduled), elastic -> rigid at the first step boundary past 0.2 s
// (asked for during the run): both swaps listed, the formulation rigid again at the end, the
// normal forces continuous at both, and each wheel's gap closed in rigid contact.
TEST(WheelsetSwap, RigidToElasticAndBack) {
  WheelsetSimulation sim(short_benchmark(0.3), contact("interp"), kR0);
  std::vector<WheelsetSnapshot> out;
  sim.on_output([&](const WheelsetSnapshot& s) { out.push_back(s); });
  sim.schedule_swap(0.1, contact("multipoint"));
  sim.start();
  while (sim.time() < 0.2 && sim.advance()) {
  }
  ASSERT_EQ(sim.formulation(), ContactFormulation::kElastic) << sim.message();
  sim.request_swap(contact("interp"));
  while (sim.advance()) {
  }
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  ASSERT_EQ(sim.swaps().size(), 2u) << sim.message();
  EXPECT_EQ(sim.swaps()[0].from, "interp");
  EXPECT_EQ(sim.swaps()[0].to, "multipoint");
  EXPECT_EQ(sim.swaps()[1].from, "multipoint");
  EXPECT_EQ(sim.swaps()[1].to, "interp");
  EXPECT_GE(sim.swaps()[1].t, 0.2);
  EXPECT_EQ(sim.formulation(), ContactFormulation::kRigid);
  expect_continuous_normal_forces(out, "interp", "multipoint", 0.0);
  expect_continuous_normal_forces(out, "multipoint", "interp", 0.2);
  // Rigid contact again: the interp model's gap at the final pose is closed on both wheels.
  const WheelsetSnapshot end = sim.snapshot();
  ContactQuery q;
  q.pose = {end.y, end.z, end.roll, end.yaw};
  q.spin_rate = end.spin_rate;
  q.normal_load = {end.wheels[0].normal_force, end.wheels[1].normal_force};
  const ContactResult c = make_contact_model("interp", test::s1002_uic60_geometry())->evaluate(q);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(c.wheels[static_cast<size_t>(i)].gap, 0.0, 1e-9) << "wheel " << i;
}

// Two scheduled swaps, scheduled out of order (the later first): both take effect, in the order
// of their times, each at the first step boundary at or after it (`wrc run --swap-at
// 0.1:multipoint,0.2:interp`; a single slot once kept only the last one scheduled).
TEST(WheelsetSwap, EveryScheduledSwapTakesEffectInTheOrderOfItsTime) {
  WheelsetSimulation sim(short_benchmark(0.3), contact("interp"), kR0);
  sim.schedule_swap(0.2, contact("interp"));
  sim.schedule_swap(0.1, contact("multipoint"));
  sim.run();
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  ASSERT_EQ(sim.swaps().size(), 2u);
  EXPECT_EQ(sim.swaps()[0].to, "multipoint");
  EXPECT_GE(sim.swaps()[0].t, 0.1);
  EXPECT_LT(sim.swaps()[0].t, 0.2);
  EXPECT_EQ(sim.swaps()[1].from, "multipoint");
  EXPECT_EQ(sim.swaps()[1].to, "interp");
  EXPECT_GE(sim.swaps()[1].t, 0.2);
  EXPECT_EQ(sim.formulation(), ContactFormulation::kRigid);
}

// A run that starts elastic (multipoint) and swaps to rigid (interp) at 0.2 s: listed, rigid
// afterwards, normal forces continuous, finished. Not earlier: an elastic start is not settled
// (its wheel loads swing by 10 % and more until about 0.15 s, measured), and the rigid
// formulation's constraint forces have no such swing; by 0.2 s the elastic loads are within 0.3 %
// of the rigid run's at that time.
TEST(WheelsetSwap, ElasticToRigid) {
  WheelsetSimulation sim(short_benchmark(0.25), contact("multipoint"), kR0);
  ASSERT_EQ(sim.formulation(), ContactFormulation::kElastic);
  std::vector<WheelsetSnapshot> out;
  sim.on_output([&](const WheelsetSnapshot& s) { out.push_back(s); });
  sim.schedule_swap(0.2, contact("interp"));
  sim.run();
  ASSERT_EQ(sim.state(), RunState::kFinished) << sim.message();
  ASSERT_EQ(sim.swaps().size(), 1u) << sim.message();
  EXPECT_EQ(sim.swaps()[0].to, "interp");
  EXPECT_EQ(sim.formulation(), ContactFormulation::kRigid);
  expect_continuous_normal_forces(out, "multipoint", "interp", 0.0);
}

}  // namespace
}  // namespace wrc
