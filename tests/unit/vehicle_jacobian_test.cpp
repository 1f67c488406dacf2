// SPDX-License-Identifier: Apache-2.0
// The vehicle's forward-difference Jacobian perturbs the columns of bodies that share no residual
// row together (jacobian_column_groups.hpp). Checked:
// - the groups of the Manchester coach (car body, two frames, four wheelsets): a body's closed
//   neighbourhood is itself and the bodies its elements join it to, and the greedy grouping puts
//   the car body alone, each frame with a wheelset of the other bogie, and the two remaining
//   wheelsets together: 4 groups, so a Newton matrix costs the residual evaluations of 4 bodies'
//   unknowns instead of 7;
// - the grouped Jacobian is the column-by-column one: each column (F(y + h e_j) - F(y)) / h with
//   the same increment h, F evaluated by VehicleDae::residual at the perturbed state alone, equal
//   with == (the rows outside a body's neighbourhood do not depend on it, so the same arithmetic
//   runs on the same numbers), at a state off the rest state where every body moves, in the
//   rigid (one-point) and the elastic (multipoint) formulation, on a curve with irregularities.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/wheelset_jacobian.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/track/track_irregularity.hpp"
#include "core/track/track_layout.hpp"
#include "core/vehicle/vehicle_file.hpp"
#include "core/vehicle_dynamics/jacobian_column_groups.hpp"
#include "core/vehicle_dynamics/vehicle_dae.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr double kR0 = 0.46;  // [m] S1002's nominal radius in the default geometry, the coach's axle height

VehicleDescription coach() {
  return read_vehicle_file(std::string(WRC_PARAMETERS_DIR) + "/vehicles/manchester-coach.json");
}

TEST(VehicleJacobian, TheCoachsBodiesFallIntoFourGroups) {
  const VehicleDescription v = coach();
  // Bodies: car_body 0, front_frame 1, front_wheelset_1 2, front_wheelset_2 3, rear_frame 4,
  // rear_wheelset_1 5, rear_wheelset_2 6.
  ASSERT_EQ(v.bodies[0].name, "car_body");
  ASSERT_EQ(v.bodies[4].name, "rear_frame");
  const JacobianColumnGroups g = jacobian_column_groups(v);
  const std::vector<std::vector<size_t>> neighbourhood{{0, 1, 4}, {0, 1, 2, 3}, {1, 2}, {1, 3},
                                                       {0, 4, 5, 6}, {4, 5}, {4, 6}};
  EXPECT_EQ(g.neighbourhood, neighbourhood);
  const std::vector<std::vector<size_t>> groups{{0}, {1, 5}, {2, 4}, {3, 6}};
  EXPECT_EQ(g.groups, groups);
}

// The grouped Jacobian against columns one at a time, with model m, at the coach's rest state on
// straight track moved off it by a lateral shift and a yaw of every body, with rates.
void expect_column_by_column(const std::string& model) {
  WheelsetParameters common;
  common.speed = 30.0;
  common.lateral_force = 0.0;
  const VehicleDescription vehicle = coach();
  VehicleEquations equations(vehicle, common, TrackLayout{}, TrackIrregularity{}, kR0,
                             static_wheel_loads(vehicle, common.gravity));
  ContactModelData data;
  if (model == "spline") data.splines = test::quick_spline_fit().model;
  auto evaluator = std::make_shared<InProcessContact>(make_contact_model(model, test::s1002_uic60_geometry(), {}, data));
  VehicleContact contact(evaluator, equations, false);
  VehicleDae dae(equations, contact);
  const double t = 2.0;  // [s]
  std::vector<double> y = vehicle_rest_state(dae, formulation_of(*evaluator), t, 1e-9, 1e-9);
  const VehicleLayout layout = dae.layout();
  const int n = layout.unknowns;
  for (size_t b = 0; b < vehicle.bodies.size(); ++b) {
    const int off = layout.offset[b];
    y[static_cast<size_t>(off + kBodyLateral)] += 1e-3 * (1.0 + 0.1 * static_cast<double>(b));
    y[static_cast<size_t>(off + kBodyYaw)] += 2e-4 * (b % 2 == 0 ? 1.0 : -1.0);
  }
  std::vector<double> yp(static_cast<size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) yp[static_cast<size_t>(i)] = 1e-3 * std::sin(1.0 + i);
  std::vector<double> r(static_cast<size_t>(n));
  dae.residual(t, y.data(), yp.data(), r.data(), true);
  std::vector<double> grouped(static_cast<size_t>(n) * static_cast<size_t>(n), 1e300);
  const long before = dae.counters().jacobian_residual_evals;
  dae.jacobian(t, 0.0, y.data(), yp.data(), r.data(), DenseMatrixView{grouped.data(), n});
  std::vector<double> state = y, column(static_cast<size_t>(n));
  int compared = 0;
  for (size_t b = 0; b < vehicle.bodies.size(); ++b) {
    const bool wheelset = equations.wheelset_of_body(b) >= 0;
    for (int k = 0; k < layout.size[b]; ++k) {
      const int j = layout.offset[b] + k;
      const double v = y[static_cast<size_t>(j)];
      state[static_cast<size_t>(j)] = v + (wheelset ? jacobian_increment(k, v) : body_jacobian_increment(k, v));
      const double h = state[static_cast<size_t>(j)] - v;
      dae.residual(t, state.data(), yp.data(), column.data());
      state[static_cast<size_t>(j)] = v;
      for (int i = 0; i < n; ++i) {
        const double expected = (column[static_cast<size_t>(i)] - r[static_cast<size_t>(i)]) / h;
        ASSERT_EQ(grouped[static_cast<size_t>(j) * static_cast<size_t>(n) + static_cast<size_t>(i)], expected)
            << model << ": row " << i << ", column " << j << " (body " << vehicle.bodies[b].name << ", unknown " << k
            << ")";
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, n * n);
  // One residual evaluation per group and unknown index: at most 4 x the largest body's unknowns
  // (one per column would be n).
  int largest = 0;
  for (int size : layout.size) largest = std::max(largest, size);
  EXPECT_LE(dae.counters().jacobian_residual_evals - before, 4 * largest) << model;
  EXPECT_LT(4 * largest, n) << model;
}

TEST(VehicleJacobian, GroupedColumnsAreTheColumnByColumnJacobianRigid) { expect_column_by_column("onepoint"); }
TEST(VehicleJacobian, GroupedColumnsAreTheColumnByColumnJacobianElastic) { expect_column_by_column("multipoint"); }

}  // namespace
}  // namespace wrc
