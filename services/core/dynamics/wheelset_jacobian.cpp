// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_jacobian.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wrc {
namespace {

// [-] relative finite-difference increment of the Jacobian: about the square root of the contact
// result's relative rounding, so that truncation and rounding errors are alike.
constexpr double kRelativeIncrement = 1e-7;
// The magnitudes below which an unknown's increment stops shrinking with it (an unknown at 0 still
// moves): scaled normal forces and multipliers [-], spin rate [rad/s], the pose and its rates
// [m, rad, m/s, rad/s].
constexpr double kTypicalScaledForce = 1.0;
constexpr double kTypicalSpinRate = 10.0;
constexpr double kTypicalPose = 1e-2;

}  // namespace

double jacobian_increment(int k, double v) {
  const double typical =
      k >= kUnknownNormalLeft ? kTypicalScaledForce : (k == kUnknownSpinRate ? kTypicalSpinRate : kTypicalPose);
  return kRelativeIncrement * std::max(std::abs(v), typical);
}

void wheelset_jacobian(const WheelsetEquations& equations, WheelsetContact& contact, double cj, const double* y,
                       const double* yp, const double* r, DenseMatrixView jac, RunCounters& counters) {
  const ContactFormulation f = contact.formulation();
  const FollowedBranches& branches = contact.branches();
  const int n = contact.unknowns();
  const bool two_point = branches.any_two_point();
  // Every perturbation that changes the contact query in one batch: one round trip.
  std::vector<ContactQuery> batch;
  std::vector<int> batch_index(static_cast<size_t>(n), -1);
  std::vector<std::vector<double>> perturbed(static_cast<size_t>(n), std::vector<double>(y, y + n));
  std::vector<double> step(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    step[k] = jacobian_increment(k, y[k]);
    perturbed[k][k] += step[k];
    step[k] = perturbed[k][k] - y[k];  // the increment actually represented
    if (!enters_contact_query(f, two_point, k)) continue;
    batch_index[static_cast<size_t>(k)] = static_cast<int>(batch.size());
    batch.push_back(equations.query(f, perturbed[k].data(), branches));
  }
  const ContactResult base = contact.at(y);
  std::vector<ContactResult> results = contact.evaluate(batch);
  ++counters.jacobian_evals;
  counters.jacobian_residual_evals += n;
  std::vector<double> column(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const int b = batch_index[static_cast<size_t>(k)];
    const ContactResult& c = b >= 0 ? results[static_cast<size_t>(b)] : base;
    equations.residual(f, perturbed[k].data(), yp, c, branches, column.data());
    for (int i = 0; i < n; ++i) jac(i, k) = (column[i] - r[i]) / step[k];
    jac(k, k) += cj * equations.derivative_coefficient(k);
  }
}

}  // namespace wrc
