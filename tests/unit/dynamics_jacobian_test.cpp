// SPDX-License-Identifier: Apache-2.0
// The Newton matrix's contact fetched with the residual before it (residual_contact): the matrix is
// the same to the last bit as when the Jacobian asks on its own, with one evaluation instead of
// two; over the paper's benchmark the next step's first state and Newton matrix travel with the
// accepted step's query, so that a step whose corrector converges at once costs one query.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/wheelset_contact.hpp"
#include "core/dynamics/wheelset_jacobian.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/models/contact_model_factory.hpp"
#include "run_to_end.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // nominal radius of the default track [m]

// An in-process contact model that notes the size of every batch it is asked.
class CountingContact final : public ContactEvaluator {
 public:
  explicit CountingContact(const std::string& model) {
    ContactModelData data;
    if (model == "spline") data.splines = test::quick_spline_fit().model;
    model_ = make_contact_model(model, test::s1002_uic60_geometry(), {}, data);
    in_process_ = std::make_shared<InProcessContact>(model_);
  }
  std::string model() const override { return model_->name(); }
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override {
    batch_sizes.push_back(batch.size());
    size_t two_point = 0;
    for (const ContactQuery& q : batch)
      two_point += std::isnan(q.second_tracked_s_wheel[0]) && std::isnan(q.second_tracked_s_wheel[1]) ? 0 : 1;
    two_point_configurations.push_back(two_point);
    return in_process_->evaluate(batch);  // follows honoured
  }
  // Batches of a Newton matrix's states alone: 11 queried unknowns with one point per wheel, 13
  // with a second point on a wheel (and then every configuration has one).
  long jacobians_alone() const {
    long n = 0;
    for (size_t i = 0; i < batch_sizes.size(); ++i)
      n += (batch_sizes[i] == 11 && two_point_configurations[i] == 0) ||
                   (batch_sizes[i] == 13 && two_point_configurations[i] == 13)
               ? 1
               : 0;
    return n;
  }
  std::vector<size_t> batch_sizes;
  std::vector<size_t> two_point_configurations;  // per batch, its configurations with a second point

 private:
  std::shared_ptr<const ContactModel> model_;
  std::shared_ptr<InProcessContact> in_process_;
};

// A rigid-contact state near the benchmark's: the wheelset 2 mm to the left and turned 1 mrad,
// rolling at the benchmark's speed, each wheel carrying half the load (scaled normal force 1).
std::vector<double> rigid_state(const WheelsetParameters& p, int unknowns) {
  std::vector<double> y(static_cast<size_t>(unknowns), 0.0);
  y[kUnknownY] = 2e-3;
  y[kUnknownZ] = kR0;
  y[kUnknownRoll] = 1e-4;
  y[kUnknownYaw] = 1e-3;
  y[kUnknownYDot] = 0.01;
  y[kUnknownYawDot] = -0.02;
  y[kUnknownSpinRate] = p.speed / kR0;
  y[kUnknownNormalLeft] = y[kUnknownNormalRight] = 1.0;
  return y;
}

std::vector<double> matrix(const WheelsetEquations& equations, WheelsetContact& contact, const std::vector<double>& y,
                           bool fetched_with_residual) {
  const int n = contact.unknowns();
  const std::vector<double> yp(static_cast<size_t>(n), 0.0);
  std::vector<double> r(static_cast<size_t>(n));
  const ContactResult& c = residual_contact(contact, y.data(), fetched_with_residual);
  equations.residual(contact.formulation(), y.data(), yp.data(), c, contact.branches(), r.data());
  std::vector<double> jac(static_cast<size_t>(n * n));
  RunCounters counters;
  wheelset_jacobian(equations, contact, 50.0, y.data(), yp.data(), r.data(), DenseMatrixView{jac.data(), n}, counters);
  return jac;
}

TEST(WheelsetJacobian, FetchedWithItsResidualTheMatrixIsTheSameInOneEvaluation) {
  for (const std::string model : {"spline", "onepoint"}) {
    const WheelsetParameters p = RunSpec{}.wheelset;
    WheelsetEquations equations(p, kR0, kR0);
    auto alone = std::make_shared<CountingContact>(model);
    auto with_residual = std::make_shared<CountingContact>(model);
    WheelsetContact contact_alone(alone, equations, false);
    WheelsetContact contact_with_residual(with_residual, equations, false);
    const std::vector<double> y = rigid_state(p, contact_alone.unknowns());
    const std::vector<double> a = matrix(equations, contact_alone, y, false);
    const std::vector<double> b = matrix(equations, contact_with_residual, y, true);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << model << ": not the same bits";
    // Queried: the pose, its rates, the spin rate and both normal forces (11 unknowns).
    EXPECT_EQ(alone->batch_sizes, (std::vector<size_t>{1, 11})) << model;
    EXPECT_EQ(with_residual->batch_sizes, (std::vector<size_t>{12})) << model;
    EXPECT_EQ(contact_alone.counters().contact_queries - contact_with_residual.counters().contact_queries, 1);
  }
}

// Over the benchmark (1 s), the queries that travel ahead: the next step's first state (IDA's
// predictor) and, where IDA's rule foresees a new Newton matrix, its perturbed states go with the
// accepted step's query, so that a step whose corrector converges at once costs one round trip.
// Every Newton matrix's states travel in a batch with other states (never alone: 11 queried
// unknowns with one point per wheel, 13 with a second point on a wheel), and IDA asks for nearly
// every predictor sent ahead. The state is the same as without the queries ahead to the last
// bit: the matrix test above at every Newton matrix, and the four models' benchmark summaries
// compared in the bus tests (tests/bus/dynamics/).
TEST(WheelsetJacobian, TheNextStepTravelsWithTheAcceptedStep) {
  for (const std::string model : {"spline", "onepoint"}) {
    RunSpec spec;
    spec.integrator.t_end = 1.0;
    spec.integrator.output_period = 0.5;
    auto counting = std::make_shared<CountingContact>(model);
    WheelsetSimulation sim(spec, counting, kR0);
    test::run_to_end(sim);
    ASSERT_EQ(sim.state(), RunState::kFinished) << model << ": " << sim.message();
    const RunCounters c = sim.counters();
    ASSERT_GT(c.jacobian_evals, 20) << model;
    ASSERT_GT(c.steps, 200) << model;
    EXPECT_EQ(counting->jacobians_alone(), 0) << model << ": Newton matrices whose contact went alone";
    EXPECT_EQ(c.contact_queries, static_cast<long>(counting->batch_sizes.size())) << model;
    // Used: every Newton matrix's states (at least 11 each) and the predictor of every step but
    // the first after a (re)start and those IDA retried with another size. Not used: a forecast
    // of a step that did not happen so (a restart at an event, a failed error test or corrector),
    // at most a predictor and a Newton matrix's 13 states each.
    EXPECT_GE(c.contact_ahead_used,
              11 * c.jacobian_evals + c.steps - (c.restarts + 1) - c.err_test_fails - c.nonlin_conv_fails)
        << model;
    EXPECT_LE(c.contact_sent_ahead - c.contact_ahead_used,
              14 * (c.restarts + c.err_test_fails + c.nonlin_conv_fails + 1))
        << model << ": sent ahead " << c.contact_sent_ahead << ", used " << c.contact_ahead_used;
  }
}

}  // namespace
}  // namespace wrc
