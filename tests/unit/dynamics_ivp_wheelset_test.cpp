// SPDX-License-Identifier: Apache-2.0
// The wheelset problem of the IVP test set (tests/support/ivp_wheelset.hpp), integrated with
// IDA and compared with the test set's published reference solution at t = 10 s; the constraints are
// checked along the whole solution. Background and the numbers measured: docs/ivp-wheelset.md.
//
// How accurate the reference itself is: runs of this implementation at rtol = atol = 1e-12 with the two
// error-control modes agree with each other to 2.2e-11 in the positions and 1.2e-9 in the velocities,
// and runs at 1e-11 and 1e-12 differ from the reference by the same amounts: 4.4e-10 m in x, 6e-11 m in
// y, 3.8e-9 rad in yaw, 1.3e-7 m/s in x', 7e-8 rad/s in the spin rate, 4.7e-10 m in the contact points'
// xi, 1.5e-10 in the scaled multipliers (1.5e-6 N). That is the reference's own global error (DASSL at
// tolerance 1e-9: about 120 times its error weight 1e-9 (1 + |y|)); it sets the floor of the bounds.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "support/ivp_wheelset.hpp"

namespace wrc {
namespace {

// Largest |ours - reference| accepted per component group, in the components' units. Each is the
// reference's own error for the group (file header: 3.8e-9, 1.3e-7, 4.7e-10, 1.5e-10) plus this run's
// error at rtol = atol = 1e-10 (measured against the 1e-12 run: 2.6e-10, 5.9e-9, 2.7e-10, 1.2e-10),
// with a margin of 1.8 to 2.9.
constexpr double kPositionBound = 1e-8;            // x, y, z [m], yaw, roll [rad]
constexpr double kVelocityBound = 4e-7;            // [m/s], [rad/s]
constexpr double kContactParameterBound = 1.5e-9;  // psi [rad], xi [m]
constexpr double kMultiplierBound = 5e-10;         // [1e4 N], i.e. 5e-6 N

double bound_for(int component) {
  if (component <= kIvpRoll) return kPositionBound;
  if (component <= kIvpSpinRate) return kVelocityBound;
  if (component <= kIvpLeftContactXi) return kContactParameterBound;
  return kMultiplierBound;
}

const char* name_of(int component) {
  static const char* const names[kIvpWheelsetDimension] = {
      "x", "y", "z", "yaw", "roll", "x'", "y'", "z'", "yaw'", "roll'", "beta'",
      "psi_R", "xi_R", "psi_L", "xi_L", "lambda_L/1e4", "lambda_R/1e4"};
  return names[component];
}

// Worst deviation of the constraints along a run, relative to their values at t = 0.
struct ConstraintDrift {
  double gap = 0;            // |gap(t) - gap(0)| [m] (position constraint, not imposed in index 2)
  double gap_rate = 0;       // |G v| [m/s] (the velocity constraint that is imposed)
  double contact_condition = 0;  // contact conditions [-]
  long steps_seen = 0;
};

IvpWheelsetStepObserver drift_observer(const IvpWheelsetParameters& p, const IvpWheelsetContactState& at_start,
                                       ConstraintDrift& drift) {
  return [&p, at_start, &drift](const IvpWheelsetState& s) {
    const IvpWheelsetContactState c = ivp_wheelset_contact_state(p, s.y);
    for (int w = 0; w < 2; ++w) {
      drift.gap = std::max(drift.gap, std::abs(c.gap[w] - at_start.gap[w]));
      drift.gap_rate = std::max(drift.gap_rate, std::abs(c.gap_rate[w]));
      drift.contact_condition =
          std::max({drift.contact_condition, std::abs(c.normal_rail_tangent[w]), std::abs(c.normal_rolling[w])});
    }
    ++drift.steps_seen;
  };
}

// The test set's initial values satisfy F(0, y0, y0') = 0 to rounding (measured max |F| = 3e-13 in
// the Newton rows [N]); their positions, given to 5 digits, miss the position constraint by ~5e-10 m,
// which the index-2 form keeps (it imposes only the constraint's rate).
TEST(IvpWheelsetModel, TestSetInitialValuesAreConsistent) {
  const IvpWheelsetParameters p;
  const IvpWheelsetState s0 = ivp_wheelset_initial_state();
  IvpWheelsetVector r{};
  ASSERT_EQ(ivp_wheelset_residual(p, s0.y, s0.yp, r), IvpWheelsetResidualStatus::kOk);
  for (int i = 0; i < kIvpWheelsetDimension; ++i) EXPECT_LE(std::abs(r[i]), 1e-11) << "row " << i;
  const IvpWheelsetContactState c = ivp_wheelset_contact_state(p, s0.y);
  for (int w = 0; w < 2; ++w) {
    EXPECT_LE(std::abs(c.gap[w]), 1e-9) << "wheel " << w;
    // Both wheels carry about half the weight m g = 157.7 N, on contact angles near the cone's 0.0262 rad.
    EXPECT_GT(c.normal_force[w], 60.0);
    EXPECT_LT(c.normal_force[w], 100.0);
    EXPECT_NEAR(c.contact_angle[w], p.cone_angle, 1e-3);
  }
}

// The reference at t = 10 s, all 17 components, with rtol = atol = 1e-10 and the algebraic unknowns
// out of the error test (SuppressAlg). Along the way: the velocity constraint and the contact
// conditions hold to ~the tolerance at every step, and the position constraint, which the index-2
// form does not impose, drifts by at most t_end x (velocity-constraint error) = 10 s x 1e-10 m/s.
TEST(IvpWheelsetReference, ReproducesPublishedSolutionAtTenSeconds) {
  const IvpWheelsetParameters p;
  const IvpWheelsetState s0 = ivp_wheelset_initial_state();
  IvpWheelsetIntegratorOptions options;
  options.relative_tolerance = 1e-10;
  options.absolute_tolerance = 1e-10;
  ConstraintDrift drift;
  const auto start = std::chrono::steady_clock::now();
  const IvpWheelsetRun run = integrate_ivp_wheelset(p, s0, kIvpWheelsetReferenceTime, options,
                                                    drift_observer(p, ivp_wheelset_contact_state(p, s0.y), drift));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  EXPECT_EQ(run.final_state.t, kIvpWheelsetReferenceTime);
  const IvpWheelsetVector reference = ivp_wheelset_reference_solution();
  double worst_relative = 0;
  for (int i = 0; i < kIvpWheelsetDimension; ++i) {
    const double error = run.final_state.y[i] - reference[i];
    EXPECT_LE(std::abs(error), bound_for(i)) << name_of(i) << ": " << run.final_state.y[i] << " vs reference "
                                             << reference[i];
    worst_relative = std::max(worst_relative, std::abs(error / reference[i]));
    std::printf("[ measured ] %-13s % .12e  reference % .12e  error % .2e\n", name_of(i), run.final_state.y[i],
                reference[i], error);
  }
  // The headline values (docs/ivp-wheelset.md, the reference at t = 10 s): lateral shift and yaw
  // to 5 digits.
  EXPECT_NEAR(run.final_state.y[kIvpLateral], 8.6355e-3, 1e-7);
  EXPECT_NEAR(run.final_state.y[kIvpYaw], -1.3642e-2, 1e-6);

  EXPECT_EQ(drift.steps_seen, run.counters.steps);
  EXPECT_LE(drift.gap, 1e-9);
  EXPECT_LE(drift.gap_rate, 1e-9);
  EXPECT_LE(drift.contact_condition, 1e-9);

  const RunCounters& c = run.counters;
  std::printf("[ measured ] rtol=atol=1e-10: worst relative error %.2e; drift: gap %.2e m, G v %.2e m/s, "
              "contact conditions %.2e\n", worst_relative, drift.gap, drift.gap_rate, drift.contact_condition);
  std::printf("[ measured ] steps %ld, residual evaluations %ld (+%ld for Jacobians), Jacobians %ld, "
              "error-test failures %ld, nonlinear failures %ld, wall %.2f s\n", c.steps, c.residual_evals,
              c.jacobian_residual_evals, c.jacobian_evals, c.err_test_fails,
              c.nonlin_conv_fails, wall);
  EXPECT_GT(c.jacobian_evals, 0);
  EXPECT_LE(c.jacobian_evals, c.lin_setups);
}

// The test set's own error control (DASSL's: only the multipliers out of the error test, by an
// absolute tolerance of 1e10 on them), at its tolerance 1e-9, lands on the same solution: at that
// tolerance the run's own error (measured against the 1e-12 run: 2.6e-9 in the positions, 7.7e-8 in
// the velocities, 7e-11 in the contact parameters, 3.6e-10 in the multipliers) adds to the
// reference's, so the bounds are twice the ones above.
TEST(IvpWheelsetReference, TestSetErrorControlAgrees) {
  const IvpWheelsetParameters p;
  IvpWheelsetIntegratorOptions options;
  options.relative_tolerance = 1e-9;
  options.absolute_tolerance = 1e-9;
  options.suppress_algebraic_error_test = false;
  const IvpWheelsetRun run = integrate_ivp_wheelset(p, ivp_wheelset_initial_state(), kIvpWheelsetReferenceTime,
                                                    options);
  const IvpWheelsetVector reference = ivp_wheelset_reference_solution();
  for (int i = 0; i < kIvpWheelsetDimension; ++i) {
    EXPECT_LE(std::abs(run.final_state.y[i] - reference[i]), 2.0 * bound_for(i)) << name_of(i);
  }
  const RunCounters& c = run.counters;
  std::printf("[ measured ] test-set error control, rtol=atol=1e-9: steps %ld, residual evaluations %ld "
              "(+%ld), Jacobians %ld, error-test failures %ld, nonlinear failures %ld\n", c.steps,
              c.residual_evals, c.jacobian_residual_evals, c.jacobian_evals,
              c.err_test_fails, c.nonlin_conv_fails);
}

template <typename Exception, typename Call>
void expect_throw_mentioning(Call call, const std::string& expected) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one mentioning '" << expected << "'";
  } catch (const Exception& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(IvpWheelsetIntegrator, RejectsBadSetUpNamingTheProblem) {
  const IvpWheelsetParameters p;
  const IvpWheelsetState s0 = ivp_wheelset_initial_state();
  IvpWheelsetIntegratorOptions bad_tolerance;
  bad_tolerance.relative_tolerance = 0.0;
  expect_throw_mentioning<std::invalid_argument>([&] { integrate_ivp_wheelset(p, s0, 1.0, bad_tolerance); },
                                                 "rtol = 0");
  expect_throw_mentioning<std::invalid_argument>([&] { integrate_ivp_wheelset(p, s0, 0.0, {}); }, "t_end = 0");

  IvpWheelsetState inconsistent = s0;
  inconsistent.yp[kIvpLateralRate] += 0.1;  // a lateral acceleration the forces do not produce
  expect_throw_mentioning<std::invalid_argument>([&] { integrate_ivp_wheelset(p, inconsistent, 1.0, {}); },
                                                 "residual row 5");

  IvpWheelsetState off_wheel = s0;
  off_wheel.y[kIvpLeftContactXi] = 4.5;  // beyond the wheel profile's outer limit (4 m)
  IvpWheelsetVector r{};
  EXPECT_EQ(ivp_wheelset_residual(p, off_wheel.y, off_wheel.yp, r), IvpWheelsetResidualStatus::kOffWheelProfile);
  expect_throw_mentioning<std::runtime_error>([&] { ivp_wheelset_contact_state(p, off_wheel.y); }, "wheel profile");

  IvpWheelsetState off_rail = s0;
  off_rail.y[kIvpLateral] = 0.07;  // the left contact point beyond the rail circle
  EXPECT_EQ(ivp_wheelset_residual(p, off_rail.y, off_rail.yp, r), IvpWheelsetResidualStatus::kOffRailProfile);
}

}  // namespace
}  // namespace wrc
