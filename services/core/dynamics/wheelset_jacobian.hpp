// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The iteration matrix dF/dy + cj dF/dy' of the wheelset's equations for IDA's Newton iteration:
/// dF/dy by forward differences, every perturbed state that changes the contact query sent in one
/// batch (one round trip to the contact model per Jacobian, or none when the residual before it
/// fetched them), dF/dy' the equations' constant diagonal.

#include <vector>

#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_contact.hpp"
#include "core/dynamics/wheelset_equations.hpp"

namespace wrc {

/// Finite-difference increment of unknown k at value v [unit of the unknown].
double jacobian_increment(int k, double v);

/// The states the forward-difference Jacobian at y perturbs, for the contact's current formulation
/// and branches.
struct JacobianPerturbations {
  std::vector<std::vector<double>> states;  ///< per unknown k: y with unknown k moved by its increment
  std::vector<double> steps;                ///< per unknown: the increment as represented [unit of the unknown]
  std::vector<bool> enters_contact;         ///< per unknown: whether it changes the contact query
  /// The states that change the contact query, in the order of their unknowns.
  std::vector<const double*> queried() const;
};
JacobianPerturbations jacobian_perturbations(const WheelsetContact& contact, const double* y);

/// The states the Jacobian at y perturbs that change the contact query, as WheelsetContact::Ahead
/// under the current placement (follows: whether they follow the points answered for the state
/// they travel with).
std::vector<WheelsetContact::Ahead> jacobian_ahead(const WheelsetContact& contact, const double* y, bool follows);

/// The contact at y for a residual. Where IDA will build a new Newton matrix right after this
/// residual (IdaIntegrator::newton_matrix_expected()), the contact of every state the Jacobian at y
/// perturbs comes in the same evaluation, so that the Jacobian finds it cached: one round trip
/// instead of two. Each configuration is evaluated on its own either way, so the results, and the
/// run, are the same to the last digit.
const ContactResult& residual_contact(WheelsetContact& contact, const double* y, bool newton_matrix_expected);

/// Writes the iteration matrix at (y, y') into jac, r = F(y, y') the residual there (the
/// equations placed on the track at the time of y). Counts jacobian_evals and
/// jacobian_residual_evals into counters.
/// @throws what the contact or the equations throw.
void wheelset_jacobian(const WheelsetEquations& equations, WheelsetContact& contact, double cj, const double* y,
                       const double* yp, const double* r, DenseMatrixView jac, RunCounters& counters);

}  // namespace wrc
