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

JacobianPerturbations jacobian_perturbations(const WheelsetContact& contact, const double* y) {
  const ContactFormulation f = contact.formulation();
  const bool two_point = contact.branches().any_two_point();
  const int n = contact.unknowns();
  JacobianPerturbations p;
  p.states.assign(static_cast<size_t>(n), std::vector<double>(y, y + n));
  p.steps.resize(static_cast<size_t>(n));
  p.enters_contact.resize(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const size_t u = static_cast<size_t>(k);
    p.states[u][u] += jacobian_increment(k, y[k]);
    p.steps[u] = p.states[u][u] - y[k];  // the increment actually represented
    p.enters_contact[u] = enters_contact_query(f, two_point, k);
  }
  return p;
}

std::vector<const double*> JacobianPerturbations::queried() const {
  std::vector<const double*> q;
  for (size_t k = 0; k < states.size(); ++k)
    if (enters_contact[k]) q.push_back(states[k].data());
  return q;
}

std::vector<WheelsetContact::Ahead> jacobian_ahead(const WheelsetContact& contact, const double* y, bool follows) {
  const JacobianPerturbations perturbations = jacobian_perturbations(contact, y);  // the states queried() points into
  std::vector<WheelsetContact::Ahead> ahead;
  for (const double* state : perturbations.queried()) ahead.push_back(contact.ahead(state, follows));
  return ahead;
}

const ContactResult& residual_contact(WheelsetContact& contact, const double* y, bool newton_matrix_expected) {
  if (!newton_matrix_expected) return contact.at(y);
  return contact.at(y, jacobian_ahead(contact, y, false));
}

void wheelset_jacobian(const WheelsetEquations& equations, WheelsetContact& contact, double cj, const double* y,
                       const double* yp, const double* r, DenseMatrixView jac, RunCounters& counters) {
  const ContactFormulation f = contact.formulation();
  const FollowedBranches& branches = contact.branches();
  const int n = contact.unknowns();
  JacobianPerturbations p = jacobian_perturbations(contact, y);
  // Every perturbation that changes the contact query in one batch (one round trip), or none
  // when the residual at y fetched them (residual_contact).
  const ContactResult base = contact.at(y);
  const std::vector<ContactResult> results = contact.at_each(p.queried());
  ++counters.jacobian_evals;
  counters.jacobian_residual_evals += n;
  std::vector<double> column(static_cast<size_t>(n));
  size_t next = 0;
  for (int k = 0; k < n; ++k) {
    const size_t u = static_cast<size_t>(k);
    const ContactResult& c = p.enters_contact[u] ? results[next++] : base;
    equations.residual(f, p.states[u].data(), yp, c, branches, column.data());
    for (int i = 0; i < n; ++i) jac(i, k) = (column[i] - r[i]) / p.steps[u];
    jac(k, k) += cj * equations.derivative_coefficient(k);
  }
}

}  // namespace wrc
