// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The solution of a tridiagonal linear system by the Thomas algorithm.

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace wrc {

/// Solves sub[i] x[i-1] + diag[i] x[i] + super[i] x[i+1] = rhs[i], i = 0..n-1 (sub[0] and
/// super[n-1] are not used), by Gaussian elimination without pivoting (the Thomas algorithm): 3 n
/// divisions and multiplications each way, stable for a diagonally dominant matrix (the callers'
/// spline equations), undefined when an elimination step meets a zero pivot.
/// @throws std::invalid_argument when n = 0 or the four sizes differ.
inline std::vector<double> solve_tridiagonal(const std::vector<double>& sub, std::vector<double> diag,
                                             const std::vector<double>& super, std::vector<double> rhs) {
  const std::size_t n = diag.size();
  if (n == 0 || sub.size() != n || super.size() != n || rhs.size() != n)
    throw std::invalid_argument("solve_tridiagonal: sub, diag, super and rhs must have the same size n >= 1");
  for (std::size_t i = 1; i < n; ++i) {
    const double w = sub[i] / diag[i - 1];
    diag[i] -= w * super[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  std::vector<double> x(n);
  x[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) x[i] = (rhs[i] - super[i] * x[i + 1]) / diag[i];
  return x;
}

}  // namespace wrc
