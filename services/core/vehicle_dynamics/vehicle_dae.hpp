// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle's equations with their contact, as IDA and the static equilibrium evaluate them: the
/// residual F(t, y, y') with every wheelset's contact in one evaluation, and the iteration matrix
/// dF/dy + cj dF/dy' by forward differences, the contact of every perturbed wheelset state in one
/// evaluation too (or none, when the residual before it fetched them), the columns of bodies that
/// share no residual row perturbed together (jacobian_column_groups.hpp).

#include <vector>

#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/vehicle_dynamics/jacobian_column_groups.hpp"
#include "core/vehicle_dynamics/vehicle_contact.hpp"
#include "core/vehicle_dynamics/vehicle_equations.hpp"

namespace wrc {

class VehicleDae {
 public:
  /// Both must outlive this.
  VehicleDae(VehicleEquations& equations, VehicleContact& contact);

  VehicleEquations& equations() { return equations_; }
  const VehicleEquations& equations() const { return equations_; }
  VehicleContact& contact() { return contact_; }
  /// The layout of the state for the wheelsets' current formulations and branches.
  VehicleLayout layout() const;

  /// F(t, y, y') into r. Where IDA builds a new Newton matrix right after this residual, the
  /// contact of every state the Jacobian will perturb comes in the same evaluation.
  /// @throws what the contact and the equations throw.
  void residual(double t, const double* y, const double* yp, double* r, bool newton_matrix_expected = false);

  /// The iteration matrix at (t, y, y') into jac (every entry written), r = F(t, y, y'). Counts
  /// jacobian_evals and jacobian_residual_evals (one per group and unknown index).
  void jacobian(double t, double cj, const double* y, const double* yp, const double* r, DenseMatrixView jac);

  /// jacobian_evals and jacobian_residual_evals so far.
  const RunCounters& counters() const { return counters_; }

 private:
  /// Each wheelset's perturbed states that change its query, for a Jacobian at y.
  std::vector<std::vector<std::vector<double>>> perturbed_contact_states(const VehicleLayout& layout,
                                                                          const double* y) const;
  VehicleEquations& equations_;
  VehicleContact& contact_;
  JacobianColumnGroups groups_;
  RunCounters counters_;
};

/// The finite-difference increment of a car body's or frame's unknown k (0..kBodyUnknowns-1) at
/// value v [unit of the unknown].
double body_jacobian_increment(int k, double v);

}  // namespace wrc
