// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_dae.hpp"

#include <algorithm>
#include <cmath>

#include "core/dynamics/wheelset_jacobian.hpp"

namespace wrc {
namespace {

// [-] relative increment, as the wheelset's Jacobian takes (wheelset_jacobian.cpp), and the
// magnitude below which it stops shrinking [m, rad, m/s, rad/s]: a body's displacements are
// millimetres to centimetres.
constexpr double kRelativeIncrement = 1e-7;
constexpr double kTypicalBodyUnknown = 1e-2;

}  // namespace

double body_jacobian_increment(int, double v) { return kRelativeIncrement * std::max(std::abs(v), kTypicalBodyUnknown); }

VehicleDae::VehicleDae(VehicleEquations& equations, VehicleContact& contact)
    : equations_(equations), contact_(contact), groups_(jacobian_column_groups(equations.vehicle())) {}

VehicleLayout VehicleDae::layout() const { return equations_.layout_of(contact_.unknowns()); }

std::vector<std::vector<std::vector<double>>> VehicleDae::perturbed_contact_states(const VehicleLayout& layout,
                                                                                   const double* y) const {
  std::vector<std::vector<std::vector<double>>> states(contact_.size());
  for (size_t w = 0; w < contact_.size(); ++w) {
    const double* own = y + layout.offset[equations_.wheelset_body(w)];
    JacobianPerturbations p = jacobian_perturbations(contact_.wheelset(w), own);
    for (size_t k = 0; k < p.states.size(); ++k)
      if (p.enters_contact[k]) states[w].push_back(std::move(p.states[k]));
  }
  return states;
}

void VehicleDae::residual(double t, const double* y, const double* yp, double* r, bool newton_matrix_expected) {
  equations_.place(t);
  const VehicleLayout layout = this->layout();
  if (newton_matrix_expected) {
    const auto perturbed = perturbed_contact_states(layout, y);
    std::vector<std::vector<const double*>> states(contact_.size());
    for (size_t w = 0; w < contact_.size(); ++w) {
      states[w].push_back(y + layout.offset[equations_.wheelset_body(w)]);
      for (const std::vector<double>& s : perturbed[w]) states[w].push_back(s.data());
    }
    contact_.fetch(states);
  }
  equations_.residual(layout, y, yp, contact_.at(layout, y), r);
}

void VehicleDae::jacobian(double t, double cj, const double* y, const double* yp, const double* r,
                          DenseMatrixView jac) {
  equations_.place(t);
  const VehicleLayout layout = this->layout();
  const int n = layout.unknowns;
  // The base contact, copied (a later lookup in a wheelset's cache may move its entries).
  std::vector<ContactResult> base;
  for (const WheelsetContactView& v : contact_.at(layout, y)) base.push_back(*v.result);
  {
    const auto perturbed = perturbed_contact_states(layout, y);
    std::vector<std::vector<const double*>> states(contact_.size());
    for (size_t w = 0; w < contact_.size(); ++w)
      for (const std::vector<double>& s : perturbed[w]) states[w].push_back(s.data());
    contact_.fetch(states);  // one evaluation, or none when the residual fetched them
  }
  ++counters_.jacobian_evals;
  std::vector<WheelsetContactView> views;
  for (size_t w = 0; w < contact_.size(); ++w) {
    const WheelsetContact& c = contact_.wheelset(w);
    views.push_back({c.formulation(), &c.branches(), &base[w]});
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) jac(i, j) = 0.0;  // a column is 0 outside its body's neighbourhood
  // Each group's bodies perturbed together, unknown k of each at once (jacobian_column_groups.hpp):
  // their neighbourhoods share no row, so each column is what perturbing it alone gives.
  std::vector<double> state(y, y + n);
  std::vector<double> column(static_cast<size_t>(n));
  std::vector<ContactResult> perturbed(contact_.size());
  std::vector<double> steps(equations_.vehicle().bodies.size());
  for (const std::vector<size_t>& group : groups_.groups) {
    int most = 0;
    for (size_t b : group) most = std::max(most, layout.size[b]);
    for (int k = 0; k < most; ++k) {
      for (size_t b : group) {
        if (k >= layout.size[b]) continue;
        const int j = layout.offset[b] + k;
        const int w = equations_.wheelset_of_body(b);
        const double h = w < 0 ? body_jacobian_increment(k, y[j]) : jacobian_increment(k, y[j]);
        state[static_cast<size_t>(j)] = y[j] + h;
        steps[b] = state[static_cast<size_t>(j)] - y[j];  // the increment as represented
        const size_t ws = static_cast<size_t>(w);
        if (w >= 0 && enters_contact_query(contact_.wheelset(ws).formulation(),
                                           contact_.wheelset(ws).branches().any_two_point(), k)) {
          perturbed[ws] = contact_.wheelset(ws).at(state.data() + layout.offset[b]);  // fetched above
          views[ws].result = &perturbed[ws];
        }
      }
      equations_.residual(layout, state.data(), yp, views, column.data());
      ++counters_.jacobian_residual_evals;
      for (size_t b : group) {
        if (k >= layout.size[b]) continue;
        const int j = layout.offset[b] + k;
        for (size_t a : groups_.neighbourhood[b])
          for (int i = layout.offset[a]; i < layout.offset[a] + layout.size[a]; ++i)
            jac(i, j) = (column[static_cast<size_t>(i)] - r[i]) / steps[b];
        const int w = equations_.wheelset_of_body(b);
        if (w >= 0) views[static_cast<size_t>(w)].result = &base[static_cast<size_t>(w)];
        state[static_cast<size_t>(j)] = y[j];
      }
    }
  }
  equations_.add_derivative_terms(layout, y, cj, jac);
}

}  // namespace wrc
