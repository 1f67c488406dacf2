// SPDX-License-Identifier: Apache-2.0
/// @file
/// solve_tridiagonal: the dense solution of the same system (Eigen's partial-pivot LU) for
/// diagonally dominant systems of every size from 1 to 40, exact on a system with a known
/// solution, and refused sizes.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/numerics/tridiagonal.hpp"

namespace {

TEST(SolveTridiagonal, MatchesTheDenseSolve) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 1; n <= 40; ++n) {
    std::vector<double> sub(static_cast<size_t>(n)), diag(static_cast<size_t>(n)), super(static_cast<size_t>(n)),
        rhs(static_cast<size_t>(n));
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) {
      const size_t k = static_cast<size_t>(i);
      sub[k] = unit(rng);
      super[k] = unit(rng);
      diag[k] = 2.5 + unit(rng);  // |diag| > |sub| + |super|: diagonally dominant
      rhs[k] = 10.0 * unit(rng);
      a(i, i) = diag[k];
      if (i > 0) a(i, i - 1) = sub[k];
      if (i + 1 < n) a(i, i + 1) = super[k];
      b[i] = rhs[k];
    }
    const std::vector<double> x = wrc::solve_tridiagonal(sub, diag, super, rhs);
    const Eigen::VectorXd dense = a.partialPivLu().solve(b);
    ASSERT_EQ(x.size(), static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) EXPECT_NEAR(x[static_cast<size_t>(i)], dense[i], 1e-13 * (1.0 + std::abs(dense[i]))) << n;
  }
}

// The second-difference matrix (-1, 2, -1) with the right-hand side of x_i = i + 1 (interior rows
// 0, the first 0, the last n + 1): the solution to rounding.
TEST(SolveTridiagonal, KnownSolution) {
  const int n = 6;
  std::vector<double> sub(n, -1.0), diag(n, 2.0), super(n, -1.0), rhs(n, 0.0);
  rhs[0] = 2.0 * 1 - 2;           // 2 x_0 - x_1 = 2 - 2
  rhs[n - 1] = 2.0 * n - (n - 1);  // -x_{n-2} + 2 x_{n-1}
  const std::vector<double> x = wrc::solve_tridiagonal(sub, diag, super, rhs);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x[static_cast<size_t>(i)], i + 1.0, 1e-14);
}

TEST(SolveTridiagonal, RefusesMismatchedSizes) {
  EXPECT_THROW(wrc::solve_tridiagonal({}, {}, {}, {}), std::invalid_argument);
  EXPECT_THROW(wrc::solve_tridiagonal({0.0}, {1.0, 1.0}, {0.0, 0.0}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(wrc::solve_tridiagonal({0.0, 0.0}, {1.0, 1.0}, {0.0, 0.0}, {1.0}), std::invalid_argument);
}

}  // namespace
