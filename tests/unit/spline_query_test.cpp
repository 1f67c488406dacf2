// SPDX-License-Identifier: Apache-2.0
// TensorSplineSet::query (the compiled per-degree kernels and the general path) against the
// tensor-product evaluation of TensorBasis::evaluate + values/derivatives: the same values,
// gradients and Hessians to rounding, for the kernel degrees (3,3,3) and (3,3,2) and for others,
// with 26 functions (the spline model's count) and 5.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/spline/tensor_spline.hpp"

namespace wrc {
namespace {

TensorSplineSet random_set(std::array<int, 3> degrees, int functions, std::mt19937& rng) {
  TensorBasis basis({BSplineBasis(degrees[0], {-0.006, -0.004, -0.001, 0.0, 0.0007, 0.003, 0.006}),
                     BSplineBasis::uniform(degrees[1], -0.001, 0.001, 2),
                     BSplineBasis::uniform(degrees[2], -0.005, 0.005, 2)});
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd c(basis.size(), functions);
  for (Eigen::Index i = 0; i < c.size(); ++i) c.data()[i] = unit(rng);
  return TensorSplineSet(basis, c);
}

TEST(SplineQuery, MatchesTheTensorProductEvaluation) {
  std::mt19937 rng(7);
  for (const std::array<int, 3> degrees :
       {std::array<int, 3>{3, 3, 3}, {3, 3, 2}, {2, 2, 2}, {3, 1, 1}, {3, 3, 0}}) {
    for (int functions : {26, 5}) {
      const TensorSplineSet set = random_set(degrees, functions, rng);
      std::uniform_real_distribution<double> y(-0.006, 0.006), r(-0.001, 0.001), w(-0.005, 0.005);
      for (int trial = 0; trial < 50; ++trial) {
        const double x[3] = {y(rng), r(rng), w(rng)};
        TensorBasisPoint p;
        set.basis().evaluate(x, SplineDerivatives::kHessian, p);
        std::vector<double> want(static_cast<size_t>(functions)), got(static_cast<size_t>(functions));
        set.values(p, want.data());
        const int nd = std::min(4, functions);
        std::vector<double> d(static_cast<size_t>(10 * nd));
        set.query(x, functions, got.data(), nd, d.data());
        for (int j = 0; j < functions; ++j) EXPECT_NEAR(got[static_cast<size_t>(j)], want[static_cast<size_t>(j)], 1e-13);
        for (int n = 0; n < nd; ++n) {
          double value, gradient[3], hessian[6];
          set.derivatives(p, n, value, gradient, hessian);
          const double* q = &d[static_cast<size_t>(10 * n)];
          EXPECT_NEAR(q[0], value, 1e-13);
          // Derivative scales: 1 / (knot spacing) per order (y: ~1e-3 m, roll: 1e-3 rad, yaw: 5e-3 rad).
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(q[1 + k], gradient[k], 1e-13 * 1e3 + 1e-12 * std::abs(gradient[k]));
          for (int k = 0; k < 6; ++k) EXPECT_NEAR(q[4 + k], hessian[k], 1e-13 * 1e6 + 1e-12 * std::abs(hessian[k]));
        }
      }
    }
  }
}

TEST(SplineQuery, RejectsCountsOutOfRange) {
  std::mt19937 rng(8);
  const TensorSplineSet set = random_set({3, 3, 3}, 5, rng);
  const double x[3] = {0, 0, 0};
  double v[8], d[60];
  EXPECT_THROW(set.query(x, 6, v, 0, d), std::invalid_argument);
  EXPECT_THROW(set.query(x, 5, v, 5, d), std::invalid_argument);
  EXPECT_THROW(set.query(x, -1, v, 0, d), std::invalid_argument);
}

}  // namespace
}  // namespace wrc
