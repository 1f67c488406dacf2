// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_restart.hpp"

#include <Eigen/Dense>

namespace wrc {

std::vector<std::vector<double>> split_by_body(const VehicleLayout& layout, const std::vector<double>& y) {
  std::vector<std::vector<double>> blocks;
  for (size_t b = 0; b < layout.offset.size(); ++b) {
    const auto first = y.begin() + layout.offset[b];
    blocks.emplace_back(first, first + layout.size[b]);
  }
  return blocks;
}

std::vector<double> join_bodies(const std::vector<std::vector<double>>& blocks) {
  std::vector<double> y;
  for (const std::vector<double>& b : blocks) y.insert(y.end(), b.begin(), b.end());
  return y;
}

std::vector<double> vehicle_consistent_derivatives(
    VehicleDae& dae, double t, std::vector<double>& y,
    const std::function<InitialisationContext(size_t wheelset)>& wheelset_initialisation) {
  VehicleEquations& e = dae.equations();
  const VehicleLayout layout = dae.layout();
  const long n = layout.unknowns;
  // The residual at y' = 0 sets every wheelset's element forces at y and gives each other body's
  // forces; dF/dy' is block diagonal, one block per body.
  std::vector<double> yp(static_cast<size_t>(n), 0.0);
  std::vector<double> r(static_cast<size_t>(n), 0.0);
  dae.residual(t, y.data(), yp.data(), r.data());
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  e.add_derivative_terms(layout, y.data(), 1.0, DenseMatrixView{d.data(), n});
  const std::vector<std::vector<double>> blocks = split_by_body(layout, y);
  for (size_t b = 0; b < blocks.size(); ++b) {
    const int offset = layout.offset[b];
    const int size = layout.size[b];
    const int w = e.wheelset_of_body(b);
    if (w < 0) {
      const Eigen::VectorXd rates =
          d.block(offset, offset, size, size).partialPivLu().solve(-Eigen::Map<const Eigen::VectorXd>(r.data() + offset, size));
      for (int k = 0; k < size; ++k) yp[static_cast<size_t>(offset + k)] = rates[k];
      continue;
    }
    std::vector<double> own = blocks[b];
    std::vector<double> own_rates;
    consistent_derivatives(wheelset_initialisation(static_cast<size_t>(w)), own, own_rates);
    for (int k = 0; k < size; ++k) {
      y[static_cast<size_t>(offset + k)] = own[static_cast<size_t>(k)];
      yp[static_cast<size_t>(offset + k)] = own_rates[static_cast<size_t>(k)];
    }
  }
  return yp;
}

}  // namespace wrc
