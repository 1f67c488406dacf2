// SPDX-License-Identifier: Apache-2.0
// A vehicle's contact costs one batch per evaluation, whatever its number of wheelsets
// (VehicleContact, docs/vehicle.md "Contact over the bus"): over the bus a batch is one round trip,
// so the Cooperrider car's four wheelsets must cost what one wheelset costs in round trips, not
// four times as many. Checked with an evaluator that notes every batch it is asked, on the car
// released with its leading wheelset 3 mm off the centre line (every body moves, so no wheelset's
// contact comes from the cache alone):
// - during the integration, batches <= residual evaluations + Newton matrices + accepted steps
//   (at most one each: IDA accepts the last Newton iterate, whose residual it did not evaluate, so
//   the contact of the accepted state is one more batch per step; a contact per wheelset would
//   give four per residual evaluation);
// - every batch of the integration carries at least four states (a residual evaluation's batch
//   is each wheelset's state);
// - the run's contact_queries and contact_configurations count exactly those batches and states.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "cone_on_circle.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.425;  // [m] the Cooperrider car's wheel radius (its axles' height)

// The in-process one-point model, noting each batch's size.
class NotingContact final : public ContactEvaluator {
 public:
  NotingContact() : in_process_(std::make_shared<InProcessContact>(make_contact_model("onepoint", test::cone_on_circle("0.05", kR0)))) {}
  std::string model() const override { return in_process_->model(); }
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override {
    batch_sizes.push_back(batch.size());
    return in_process_->evaluate(batch);
  }
  std::vector<size_t> batch_sizes;

 private:
  std::shared_ptr<InProcessContact> in_process_;
};

TEST(VehicleContactBatch, TheCarsFourWheelsetsCostOneBatchPerEvaluation) {
  VehicleRunSpec spec;
  spec.vehicle = read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/cooperrider-car.json");
  spec.run.wheelset.speed = 30.0;
  spec.run.wheelset.material.friction = 10.0;
  spec.run.wheelset.lateral_force = 0.0;
  spec.run.initial.y = 3e-3;
  spec.run.integrator.t_end = 0.5;
  auto noting = std::make_shared<NotingContact>();
  VehicleSimulation run(spec, noting, kR0);
  ASSERT_EQ(run.equations().wheelset_count(), 4u);
  run.start();
  const size_t at_start = noting->batch_sizes.size();
  const RunCounters before = run.counters();
  while (run.advance()) {
  }
  ASSERT_EQ(run.state(), RunState::kFinished) << run.message();
  const RunCounters after = run.counters();
  const std::vector<size_t> integration(noting->batch_sizes.begin() + static_cast<std::ptrdiff_t>(at_start),
                                        noting->batch_sizes.end());
  const long evaluations = (after.residual_evals - before.residual_evals) +
                           (after.jacobian_evals - before.jacobian_evals) + (after.steps - before.steps);
  ASSERT_GT(integration.size(), 20u);
  EXPECT_LE(static_cast<long>(integration.size()), evaluations);
  EXPECT_GE(*std::min_element(integration.begin(), integration.end()), 4u);
  // The counters are the batches and states sent, start included.
  EXPECT_EQ(after.contact_queries, static_cast<long>(noting->batch_sizes.size()));
  EXPECT_EQ(after.contact_configurations,
            static_cast<long>(std::accumulate(noting->batch_sizes.begin(), noting->batch_sizes.end(), size_t{0})));
}

}  // namespace
}  // namespace wrc
