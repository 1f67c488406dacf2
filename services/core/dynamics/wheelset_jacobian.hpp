// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The iteration matrix dF/dy + cj dF/dy' of the wheelset's equations for IDA's Newton iteration:
/// dF/dy by forward differences, every perturbed state that changes the contact query sent in one
/// batch (one round trip to the contact model per Jacobian), dF/dy' the equations' constant
/// diagonal.

#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_contact.hpp"
#include "core/dynamics/wheelset_equations.hpp"

namespace wrc {

/// Finite-difference increment of unknown k at value v [unit of the unknown].
double jacobian_increment(int k, double v);

/// Writes the iteration matrix at (y, y') into jac, r = F(y, y') the residual there (the
/// equations placed on the track at the time of y). Counts jacobian_evals and
/// jacobian_residual_evals into counters.
/// @throws what the contact or the equations throw.
void wheelset_jacobian(const WheelsetEquations& equations, WheelsetContact& contact, double cj, const double* y,
                       const double* yp, const double* r, DenseMatrixView jac, RunCounters& counters);

}  // namespace wrc
