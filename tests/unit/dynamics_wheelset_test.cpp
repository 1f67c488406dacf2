// SPDX-License-Identifier: Apache-2.0
// The wheelset dynamics (WheelsetSimulation, in-process contact): energy conservation without
// friction and damping, the kinematic (Klingel) wavelength of a free wheelset, mirror symmetry,
// the force balance of the benchmark's quasi-steady state, swaps (reproducible with schedule_swap,
// rigid to elastic) and the run parameter file.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/run_parameters_file.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/geometry/conicity.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/models/contact_model_factory.hpp"
#include "run_to_end.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

std::shared_ptr<ContactEvaluator> contact(const std::string& model) {
  static const std::shared_ptr<const ContactModel> interp = make_contact_model("interp", test::s1002_uic60_geometry());
  if (model == "interp") return std::make_shared<InProcessContact>(interp);
  ContactModelData data;
  if (model == "spline") data.splines = test::quick_spline_fit().model;
  return std::make_shared<InProcessContact>(make_contact_model(model, test::s1002_uic60_geometry(), {}, data));
}

std::vector<WheelsetSnapshot> run(WheelsetSimulation& sim) { return test::run_to_end(sim); }

// Total mechanical energy: kinetic, the constant vertical load's potential, the springs [J].
double energy(const WheelsetSnapshot& s, const WheelsetParameters& p, double z_reference) {
  const PrimarySuspension& k = p.suspension;
  const double b2 = k.half_spacing * k.half_spacing;
  return 0.5 * p.mass * (s.y_dot * s.y_dot + s.z_dot * s.z_dot) + 0.5 * p.roll_inertia * s.roll_dot * s.roll_dot +
         0.5 * p.yaw_inertia * s.yaw_dot * s.yaw_dot + 0.5 * p.spin_inertia * s.spin_rate * s.spin_rate +
         p.total_vertical_load() * s.z - p.lateral_force * s.y + k.lateral_stiffness * s.y * s.y +
         k.vertical_stiffness * (s.z - z_reference) * (s.z - z_reference) + k.vertical_stiffness * b2 * s.roll * s.roll +
         k.longitudinal_stiffness * b2 * s.yaw * s.yaw;
}

// Without friction (no creep forces), dampers and lateral load the rigid-contact DAE is
// conservative: the constraint forces act along the gap gradients, orthogonal to every admissible
// velocity. The spline model's gap gradient is the exact derivative of its (C2) gap, so the energy
// of a 2 mm lateral oscillation is kept to the integration error; bound 1e-3 of the oscillation's
// kinetic energy.
TEST(WheelsetDynamics, EnergyIsConservedWithoutFrictionAndDamping) {
  RunSpec spec;
  spec.wheelset.material.friction = 0.0;
  spec.wheelset.lateral_force = 0.0;
  spec.wheelset.suspension = PrimarySuspension::none();
  spec.wheelset.suspension.lateral_stiffness = 2e6;
  spec.wheelset.suspension.longitudinal_stiffness = 1e6;
  spec.wheelset.suspension.vertical_stiffness = 6e5;
  spec.initial.y = 2e-3;
  spec.integrator.t_end = 0.5;
  spec.integrator.relative_tolerance = 1e-8;
  spec.integrator.position_tolerance = 1e-10;
  spec.integrator.velocity_tolerance = 1e-8;
  spec.integrator.output_period = 1e-3;
  WheelsetSimulation sim(spec, contact("spline"), kR0);
  const std::vector<WheelsetSnapshot> out = run(sim);
  const double z_ref = sim.equations().z_reference();
  const double e0 = energy(out.front(), spec.wheelset, z_ref);
  double worst = 0.0, swing = 0.0;
  for (const WheelsetSnapshot& s : out) {
    worst = std::max(worst, std::abs(energy(s, spec.wheelset, z_ref) - e0));
    swing = std::max(swing, 0.5 * spec.wheelset.mass * s.y_dot * s.y_dot);
  }
  ASSERT_GT(swing, 1.0);  // it does oscillate (kinetic energy of the lateral motion [J])
  EXPECT_LT(worst, 1e-3 * swing) << "energy drift " << worst << " J of " << swing << " J";
  std::cout << "[ measured ] energy drift " << worst << " J, lateral kinetic energy up to " << swing << " J\n";
}

// Klingel: a free wheelset (no suspension, no load but its weight, low speed) rolls on the tread
// in a kinematic oscillation of wavelength 2 pi sqrt(r0 e / lambda_e). lambda_e: equivalent
// conicity at the amplitude, r0 and e (half the distance of the contact points) of the centred
// wheelset, all from the exact geometry. With the spline model (whose rolling radii are fitted to
// the exact ones) the measured wavelength lies 1 % above the kinematic one (creep and
// gravitational stiffness make the motion slightly non-kinematic); bound 5 %.
TEST(WheelsetDynamics, FreeWheelsetHasTheKinematicWavelength) {
  const double amplitude = 3e-3;
  RunSpec spec;
  spec.wheelset.lateral_force = 0.0;
  spec.wheelset.vertical_force = 0.0;
  spec.wheelset.suspension = PrimarySuspension::none();
  spec.wheelset.speed = 5.0;
  spec.initial.y = amplitude;
  spec.integrator.t_end = 6.0;
  spec.integrator.output_period = 2e-3;
  WheelsetSimulation sim(spec, contact("spline"), kR0);
  const std::vector<WheelsetSnapshot> out = run(sim);
  std::vector<double> up_crossings;
  for (size_t k = 1; k < out.size(); ++k)
    if (out[k - 1].y < 0.0 && out[k].y >= 0.0)
      up_crossings.push_back(out[k - 1].t + (out[k].t - out[k - 1].t) * (-out[k - 1].y) / (out[k].y - out[k - 1].y));
  ASSERT_GE(up_crossings.size(), 2u) << "no oscillation";
  const double period = (up_crossings.back() - up_crossings.front()) / static_cast<double>(up_crossings.size() - 1);
  const double wavelength = spec.wheelset.speed * period;
  const RigidWheelsetSolver solver(*test::s1002_uic60_geometry());
  const RigidContact centred = solver.solve(0.0, 0.0);
  const double e = 0.5 * (centred.left().wheel_point.y() - centred.right().wheel_point.y());
  const double r0 = 0.5 * (centred.left().rolling_radius + centred.right().rolling_radius);
  const double conicity = equivalent_conicity(solver, amplitude);
  const double kinematic = 2.0 * M_PI * std::sqrt(r0 * e / conicity);
  std::cout << "[ measured ] wavelength " << wavelength << " m, kinematic " << kinematic << " m (conicity "
            << conicity << ", e " << e << " m, r0 " << r0 << " m)\n";
  EXPECT_NEAR(wavelength, kinematic, 0.05 * kinematic);
}

// Mirror symmetry: the lateral load reversed gives the mirrored motion (y, roll, yaw change sign,
// z does not; the wheels swap). Bound: 1e-9 m / rad (rounding only).
TEST(WheelsetDynamics, MirroredLoadGivesMirroredMotion) {
  RunSpec spec;
  spec.integrator.t_end = 0.3;
  spec.integrator.output_period = 0.3;
  RunSpec mirrored = spec;
  mirrored.wheelset.lateral_force = -spec.wheelset.lateral_force;
  WheelsetSimulation a(spec, contact("interp"), kR0), b(mirrored, contact("interp"), kR0);
  const WheelsetSnapshot sa = run(a).back(), sb = run(b).back();
  EXPECT_GT(std::abs(sa.y), 1e-3);
  EXPECT_NEAR(sa.y, -sb.y, 1e-9);
  EXPECT_NEAR(sa.roll, -sb.roll, 1e-9);
  EXPECT_NEAR(sa.yaw, -sb.yaw, 1e-9);
  EXPECT_NEAR(sa.z, sb.z, 1e-9);
  EXPECT_NEAR(sa.wheels[0].normal_force, sb.wheels[1].normal_force, 1e-3);
}

// The benchmark (spline model) reaches a quasi-steady state in which the contact forces, as the
// rigid-contact equations apply them (normal forces along the gap gradients, creep forces),
// balance the external loads: lateral within 0.1 % of Fy, vertical within 0.01 % of the load.
TEST(WheelsetDynamics, BenchmarkEndsInForceBalance) {
  RunSpec spec;
  spec.integrator.t_end = 1.5;
  spec.integrator.output_period = 0.5;
  WheelsetSimulation sim(spec, contact("spline"), kR0);
  const WheelsetSnapshot s = run(sim).back();
  EXPECT_LT(std::abs(s.y_dot), 1e-6);
  EXPECT_LT(std::abs(s.yaw_dot), 1e-6);
  EXPECT_EQ(sim.counters().restarts, 0);  // the spline model has no jumps on the tread
  ContactQuery q;
  q.pose = {s.y, s.z, s.roll, s.yaw};
  q.spin_rate = s.spin_rate;
  q.normal_load = {s.wheels[0].normal_force, s.wheels[1].normal_force};
  q.speed = spec.wheelset.speed;
  const ContactResult c = make_contact_model("spline", test::s1002_uic60_geometry(), {},
                                             ContactModelData{test::quick_spline_fit().model})
                              ->evaluate(q);
  const WheelsetParameters& p = spec.wheelset;
  Eigen::Vector4d contact_force(c.creep_force.y(), c.creep_force.z(), 0.0, 0.0);
  for (int i = 0; i < 2; ++i)
    contact_force += s.wheels[i].normal_force * c.wheels[i].normal_z * c.wheels[i].gap_gradient;
  EXPECT_NEAR(contact_force[0] + p.lateral_force, 0.0, 1e-3 * std::abs(p.lateral_force));
  const double suspension_z = 2.0 * p.suspension.vertical_stiffness * (s.z - sim.equations().z_reference());
  EXPECT_NEAR(contact_force[1] - suspension_z, p.total_vertical_load(), 1e-4 * p.total_vertical_load());
  std::cout << "[ measured ] benchmark with spline: y " << s.y << " m, yaw " << s.yaw << " rad, lateral balance "
            << contact_force[0] + p.lateral_force << " N; the fitted normals' resultant differs by "
            << c.force.y() - contact_force[0] << " N\n";
}

// A swap asked for during a run takes effect at a step boundary and is listed; a second run with
// that time scheduled reproduces the first bit for bit.
TEST(WheelsetDynamics, SwapIsReproducedByScheduledSwap) {
  RunSpec spec;
  spec.integrator.t_end = 0.3;
  spec.integrator.output_period = 0.3;
  WheelsetSimulation live(spec, contact("interp"), kR0);
  live.start();
  while (live.time() < 0.1 && live.advance()) {
  }
  live.request_swap(contact("onepoint"));
  while (live.advance()) {
  }
  ASSERT_EQ(live.state(), RunState::kFinished) << live.message();
  ASSERT_EQ(live.swaps().size(), 1u);
  const double t_swap = live.swaps().front().t;
  EXPECT_GE(t_swap, 0.1);
  EXPECT_EQ(live.swaps().front().to, "onepoint");
  WheelsetSimulation replay(spec, contact("interp"), kR0);
  replay.schedule_swap(t_swap, contact("onepoint"));
  replay.run();
  ASSERT_EQ(replay.state(), RunState::kFinished) << replay.message();
  ASSERT_EQ(replay.swaps().size(), 1u);
  EXPECT_EQ(replay.swaps().front().t, t_swap);
  const WheelsetSnapshot a = live.snapshot(), b = replay.snapshot();
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.roll, b.roll);
  EXPECT_EQ(a.yaw, b.yaw);
  EXPECT_EQ(a.y_dot, b.y_dot);
  EXPECT_EQ(live.counters().steps, replay.counters().steps);
}

// Rigid to elastic: the elastic contact is settled to the rigid normal forces, so the normal
// forces go on continuously (within 2 %), and the run finishes (and back, and elastic to rigid:
// dynamics_swap_test.cpp).
TEST(WheelsetDynamics, SwapBetweenRigidAndElasticIsConsistent) {
  RunSpec spec;
  spec.integrator.t_end = 0.3;
  spec.integrator.output_period = 1e-3;
  WheelsetSimulation sim(spec, contact("interp"), kR0);
  sim.schedule_swap(0.1, contact("multipoint"));
  std::vector<WheelsetSnapshot> out = run(sim);
  ASSERT_EQ(sim.swaps().size(), 1u);
  EXPECT_EQ(sim.formulation(), ContactFormulation::kElastic);
  for (size_t k = 1; k < out.size(); ++k) {
    if (out[k - 1].t < 0.1 && out[k].t >= 0.1) {
      for (int i = 0; i < 2; ++i)
        EXPECT_NEAR(out[k].wheels[i].normal_force, out[k - 1].wheels[i].normal_force,
                    0.02 * out[k - 1].wheels[i].normal_force);
    }
  }
}

TEST(RunParameterFile, RoundTripAndErrors) {
  RunSpec spec;
  spec.wheelset.speed = 12.5;
  spec.wheelset.include_gravity = false;
  spec.integrator.max_steps = 1234;
  RunSpec read;
  apply_run_parameters(run_parameter_text(spec), "written", read);
  EXPECT_EQ(read.wheelset.speed, 12.5);
  EXPECT_FALSE(read.wheelset.include_gravity);
  EXPECT_EQ(read.integrator.max_steps, 1234);
  EXPECT_EQ(read.wheelset.suspension.longitudinal_stiffness, spec.wheelset.suspension.longitudinal_stiffness);
  auto error = [](const std::string& text) {
    RunSpec s;
    try {
      apply_run_parameters(text, "p.json", s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(R"({"speeed": 3})").find("p.json: speeed: unknown parameter"), std::string::npos);
  EXPECT_NE(error(R"({"speed": -3})").find("speed = -3"), std::string::npos);
  // g = 0 would make the load's apparent gravity V^2 kappa / g = 0 / 0 on straight track (the run
  // failed at t = 0 with y_dot = NaN in its first query): refused.
  EXPECT_NE(error(R"({"gravity": 0})").find("gravity = 0"), std::string::npos) << error(R"({"gravity": 0})");
  EXPECT_NE(error(R"({"include_gravity": 1})").find("include_gravity: must be true or false"), std::string::npos);
  EXPECT_NE(error(R"({"max_steps": 2.5})").find("not a whole number"), std::string::npos);
  EXPECT_NE(error("[1, 2]").find("one JSON object"), std::string::npos);
  EXPECT_EQ(error("{ // comment\n \"mass\": 1500 }"), "no error");
}

// The shipped benchmark parameter file holds exactly the built-in defaults (RunSpec{}), so that a
// user's copy starts from what `wrc run` does without one.
TEST(RunParameterFile, ShippedBenchmarkFileIsTheDefault) {
  RunSpec read;
  read.wheelset.mass = 1.0;  // every key must be in the file and overwrite this
  apply_run_parameter_file(std::string(WRC_PARAMETERS_DIR) + "/benchmark.json", read);
  const RunSpec defaults;
  for (const RunParameter& p : run_parameter_table()) EXPECT_EQ(p.get(read), p.get(defaults)) << p.key;
}

// The second shipped file is the benchmark with the paper's lost Greek letter read as mu = 0.01:
// every key present, only the friction differs.
TEST(RunParameterFile, ShippedLowFrictionFileDiffersOnlyInFriction) {
  RunSpec read;
  read.wheelset.mass = 1.0;
  apply_run_parameter_file(std::string(WRC_PARAMETERS_DIR) + "/benchmark-mu001.json", read);
  const RunSpec defaults;
  EXPECT_EQ(read.wheelset.material.friction, 0.01);
  for (const RunParameter& p : run_parameter_table()) {
    if (std::string(p.key) == "friction") continue;
    EXPECT_EQ(p.get(read), p.get(defaults)) << p.key;
  }
}

// A contact source that answers its first queries from the multi-point model and then, as a
// model does outside its range, refuses every configuration (ContactConfigurationError).
class FailingAfter final : public ContactEvaluator {
 public:
  FailingAfter(const std::string& model, long answers)
      : model_(make_contact_model(model, test::s1002_uic60_geometry())), left_(answers) {}
  std::string model() const override { return model_.model(); }
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override {
    if (--left_ < 0) throw ContactConfigurationError("test: configuration refused");
    return model_.evaluate(batch);  // follows honoured
  }

 private:
  InProcessContact model_;
  long left_;
};

// When the integrator gives up, the run's message has the contact's error and IDA's own text, and
// IDA prints nothing itself (its messages go to the run: a failure the run recovers from, a
// convergence restart of rigid contact, would otherwise print "[IDA ERROR]" to a user's terminal).
// Rigid contact (onepoint): the evaluation that fails first is one IDA asks for, the event
// functions' at an accepted step.
TEST(WheelsetSimulation, SolverFailureMessageHasIdasTextAndNothingIsPrinted) {
  RunSpec spec;
  spec.integrator.t_end = 1.0;
  WheelsetSimulation sim(spec, std::make_shared<FailingAfter>("onepoint", 200), kR0);
  testing::internal::CaptureStderr();
  sim.run();
  const std::string printed = testing::internal::GetCapturedStderr();
  ASSERT_EQ(sim.state(), RunState::kFailed);
  EXPECT_NE(sim.message().find("IDASolve failed"), std::string::npos) << sim.message();
  EXPECT_NE(sim.message().find("test: configuration refused"), std::string::npos) << sim.message();
  EXPECT_NE(sim.message().find("(IDARcheck3: "), std::string::npos) << sim.message();  // IDA's function and text
  EXPECT_EQ(printed.find("IDA ERROR"), std::string::npos) << printed;
  std::cout << "[ measured ] " << sim.message() << "\n";
}

// Elastic contact (multipoint) has no event functions: the accepted step's contact is asked for
// after IDA returns (with the next step's states, WheelsetSimulation::after_step), and a failure
// there ends the run with the contact's error and the time of the step.
TEST(WheelsetSimulation, AFailureAfterTheStepNamesItsTime) {
  RunSpec spec;
  spec.integrator.t_end = 1.0;
  WheelsetSimulation sim(spec, std::make_shared<FailingAfter>("multipoint", 200), kR0);
  sim.run();
  ASSERT_EQ(sim.state(), RunState::kFailed);
  EXPECT_EQ(sim.message().rfind("at t = ", 0), 0u) << sim.message();
  EXPECT_NE(sim.message().find(" s: test: configuration refused"), std::string::npos) << sim.message();
  EXPECT_GT(sim.counters().steps, 50);
  std::cout << "[ measured ] " << sim.message() << "\n";
}

}  // namespace
}  // namespace wrc
