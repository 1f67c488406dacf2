// SPDX-License-Identifier: Apache-2.0
/// @file
/// The spline model's query takes the compiled fast path, and that path is right in the shape the
/// model calls it. SplineModel evaluates each wheel with kSplineQueryFieldCount (22) values and
/// one derivative function (z's value, gradient and Hessian; spline_model.cpp), which
/// TensorSplineSet::query runs through the compiled kernel of 6 blocks of 4 functions, not the
/// 26-value / 4-derivative shape spline_query_test.cpp checks. Here:
///  - every branch of both wheels of a fitted S1002/UIC60 model (default degrees 3, 3, 3) and a
///    (3, 3, 2) set report query_is_compiled for that shape (a kernel table without their row,
///    or a select that returns none, fails here instead of silently running the general path);
///  - in that shape, the compiled path equals the general tensor-product evaluation
///    (TensorBasis::evaluate + values / derivatives) at 200 points per branch of the fitted model
///    and of random sets.
///
/// Tolerance: each output is a sum of at most 64 products coefficient x basis weight; both paths
/// round such a sum within 64 eps sum_t |c_t w_t| (eps = 1.1e-16), about 7e-15 of that sum each,
/// in different orders (the kernel sums by lanes and, in its AVX2 clone, with FMAs). The bound is
/// 1e-13 x sum_t |c_t w_t| (computed per output from the evaluated basis point), seven times the
/// two paths' worst-case rounding together, and far below any error of a wrong term or factor
/// (which is of the size of the sum itself).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/spline/spline_fields.hpp"
#include "core/spline/tensor_spline.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

constexpr int kValues = kSplineQueryFieldCount;  // what SplineModel asks for
constexpr int kDerivatives = 1;                  // z only

// sum_t |c_t w_t| of function j for the weights w (one of the basis point's arrays).
double magnitude(const TensorSplineSet& set, const TensorBasisPoint& p, const std::array<double, kMaxTensorTerms>& w,
                 int j) {
  double sum = 0.0;
  for (int t = 0; t < p.terms; ++t)
    sum += std::abs(set.coefficient(p.index[static_cast<size_t>(t)], j) * w[static_cast<size_t>(t)]);
  return sum;
}

// The production shape at `points` random points of the set's box, against the general path.
void expect_query_matches_general_path(const TensorSplineSet& set, int points, std::mt19937& rng,
                                       const std::string& what) {
  ASSERT_GE(set.functions(), kValues) << what;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < points; ++trial) {
    double x[3];
    for (int k = 0; k < 3; ++k) {
      const BSplineBasis& b = set.basis().basis(k);
      x[k] = b.lower() + (b.upper() - b.lower()) * unit(rng);
    }
    std::vector<double> got(static_cast<size_t>(kValues)), d(10 * kDerivatives);
    set.query(x, kValues, got.data(), kDerivatives, d.data());
    TensorBasisPoint p;
    set.basis().evaluate(x, SplineDerivatives::kHessian, p);
    std::vector<double> want(static_cast<size_t>(set.functions()));
    set.values(p, want.data());
    for (int j = 0; j < kValues; ++j)
      ASSERT_NEAR(got[static_cast<size_t>(j)], want[static_cast<size_t>(j)], 1e-13 * magnitude(set, p, p.value, j))
          << what << ", field " << j << " at (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
    double value, gradient[3], hessian[6];
    set.derivatives(p, 0, value, gradient, hessian);
    ASSERT_NEAR(d[0], value, 1e-13 * magnitude(set, p, p.value, 0)) << what << ", z";
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(d[static_cast<size_t>(1 + k)], gradient[k], 1e-13 * magnitude(set, p, p.gradient[static_cast<size_t>(k)], 0))
          << what << ", dz/dv" << k;
    for (int k = 0; k < 6; ++k)
      ASSERT_NEAR(d[static_cast<size_t>(4 + k)], hessian[k], 1e-13 * magnitude(set, p, p.hessian[static_cast<size_t>(k)], 0))
          << what << ", Hessian slot " << k;
  }
}

// The fitted S1002/UIC60 model (the quick test fit: default box, knots and degrees): every branch
// of both wheels runs the compiled kernel for the model's query, and it equals the general path.
TEST(SplineQueryFastPath, FittedModelTakesTheCompiledPath) {
  const SplineContactGeometry& model = *test::quick_spline_fit().model;
  std::mt19937 rng(17);
  int branches = 0;
  for (const WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const SplineWheel& wheel = model.wheel(side);
    for (size_t m = 0; m < wheel.branches.size(); ++m) {
      const TensorSplineSet& set = wheel.branches[m];
      const std::string what = std::string(side == WheelSide::kLeft ? "left" : "right") + " branch " + std::to_string(m);
      ASSERT_EQ(set.functions(), kSplineFieldCount) << what;
      EXPECT_TRUE(set.query_is_compiled(kValues)) << what << ": the model's query runs the general path";
      expect_query_matches_general_path(set, 200, rng, what);
      ++branches;
    }
  }
  EXPECT_GE(branches, 2);
}

// Random coefficients on the two degree combinations the kernels are compiled for, 26 functions
// (the model's count): compiled for the query shape, and equal to the general path. A (2, 2, 2)
// set is not compiled (the general path; the predicate must be able to say no).
TEST(SplineQueryFastPath, KernelDegreesInTheQueryShape) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const std::array<int, 3> degrees : {std::array<int, 3>{3, 3, 3}, {3, 3, 2}, {2, 2, 2}}) {
    TensorBasis basis({BSplineBasis(degrees[0], {-0.006, -0.004, -0.001, 0.0, 0.0007, 0.003, 0.006}),
                       BSplineBasis::uniform(degrees[1], -0.001, 0.001, 2),
                       BSplineBasis::uniform(degrees[2], -0.005, 0.005, 2)});
    Eigen::MatrixXd c(basis.size(), kSplineFieldCount);
    for (Eigen::Index i = 0; i < c.size(); ++i) c.data()[i] = unit(rng);
    const TensorSplineSet set(basis, c);
    const std::string what = "degrees " + std::to_string(degrees[0]) + std::to_string(degrees[1]) +
                             std::to_string(degrees[2]);
    const bool kernel_degrees = degrees[0] == 3 && degrees[1] == 3;  // (3, 3, 3) and (3, 3, 2)
    EXPECT_EQ(set.query_is_compiled(kValues), kernel_degrees) << what;
    EXPECT_EQ(set.query_is_compiled(kSplineFieldCount), kernel_degrees) << what;
    expect_query_matches_general_path(set, 200, rng, what);
  }
}

}  // namespace
}  // namespace wrc
