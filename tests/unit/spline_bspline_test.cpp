// SPDX-License-Identifier: Apache-2.0
/// @file
/// Unit tests of the B-spline bases (services/core/spline): the 1-D basis (partition of unity,
/// derivatives, continuity, argument checks) and the tensor-product evaluation with its contraction
/// (gradient and Hessian against finite differences, index order).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/spline/bspline_basis.hpp"
#include "core/spline/tensor_spline.hpp"
#include "expect_invalid.hpp"

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Nonuniform breakpoints on [0, 1], smallest spacing 0.05.
const std::vector<double> kBreaks = {0.0, 0.1, 0.35, 0.4, 0.8, 1.0};

using wrc::test::expect_invalid;

// Bound on |d^a/dx^a sum_i c_i N_i| for |c_i| <= 1: differentiating a spline differences its
// coefficients and divides by knot spans >= the smallest interval hmin, each step a factor
// 2 (p - step) / hmin on a partition of unity: 2^a p! / (p - a)! / hmin^a, and 0 for a > p.
double derivative_bound(const wrc::BSplineBasis& basis, int a) {
  const int p = basis.degree();
  if (a > p) return 0.0;
  const auto& b = basis.breakpoints();
  double hmin = b[1] - b[0];
  for (size_t i = 1; i + 1 < b.size(); ++i) hmin = std::min(hmin, b[i + 1] - b[i]);
  double bound = 1.0;
  for (int s = 0; s < a; ++s) bound *= 2.0 * (p - s) / hmin;
  return bound;
}

// Bound on the mixed derivative of order alpha of a tensor spline with |c| <= 1 (1-D bounds multiply).
double derivative_bound(const wrc::TensorBasis& basis, const std::vector<int>& alpha) {
  double bound = 1.0;
  for (int k = 0; k < basis.dimension(); ++k) bound *= derivative_bound(basis.basis(k), alpha[static_cast<size_t>(k)]);
  return bound;
}

// Error bound of a central difference (g(x+h) - g(x-h)) / 2h of a quantity bounded by `scale`
// whose third derivative is bounded by `third`: truncation h^2/6 third, plus rounding of two
// evaluations of at most 64 terms each (64 eps scale each) and of x +- h (eps |x| |g'|, |g'| folded
// into scale / h by the choice of h): (2 * 64 + 2) eps scale / 2h.
double central_difference_tolerance(double h, double third, double scale) {
  return h * h / 6.0 * third + 65.0 * kEps * scale / h;
}

// All n basis functions (zero outside the evaluated ones) and their derivatives at x.
struct FullBasis {
  std::vector<double> value, d1, d2;
};
FullBasis full_basis(const wrc::BSplineBasis& basis, double x) {
  FullBasis f{std::vector<double>(static_cast<size_t>(basis.size())), std::vector<double>(static_cast<size_t>(basis.size())),
              std::vector<double>(static_cast<size_t>(basis.size()))};
  double v[4], d1[4], d2[4];
  const int first = basis.evaluate(x, v, d1, d2);
  for (int r = 0; r <= basis.degree(); ++r) {
    const size_t i = static_cast<size_t>(first + r);
    f.value[i] = v[r];
    f.d1[i] = d1[r];
    f.d2[i] = d2[r];
  }
  return f;
}

// Verifies, for degrees 0..3 on nonuniform breakpoints at 2001 points and the ends: the basis
// values are >= 0 (inside the box the Bernstein form combines non-negative coefficients with
// non-negative weights) and sum to 1 within 8 eps (rounding of a sum of <= 4 terms), the derivatives of the sum
// vanish to 1e-13 of sum |N'| (the derivative weights cancel, rounding only), the returned first
// index is interval(x), and the knot sequence has size() + degree + 1 entries.
TEST(SplineBasis, PartitionOfUnityAndNonnegativity) {
  for (int p = 0; p <= wrc::kMaxSplineDegree; ++p) {
    const wrc::BSplineBasis basis(p, kBreaks);
    EXPECT_EQ(basis.size(), 5 + p);
    EXPECT_EQ(static_cast<int>(basis.knots().size()), basis.size() + p + 1);
    for (int s = 0; s <= 2000; ++s) {
      const double x = s / 2000.0;
      double v[4], d1[4], d2[4];
      const int first = basis.evaluate(x, v, d1, d2);
      EXPECT_EQ(first, basis.interval(x));
      double sum = 0, sum1 = 0, sum2 = 0, abs1 = 0, abs2 = 0;
      for (int r = 0; r <= p; ++r) {
        EXPECT_GE(v[r], 0.0) << "p " << p << " x " << x;
        sum += v[r];
        sum1 += d1[r];
        sum2 += d2[r];
        abs1 += std::abs(d1[r]);
        abs2 += std::abs(d2[r]);
      }
      EXPECT_NEAR(sum, 1.0, 8 * kEps) << "p " << p << " x " << x;
      EXPECT_LE(std::abs(sum1), 1e-13 * abs1 + 1e-300) << "p " << p << " x " << x;
      EXPECT_LE(std::abs(sum2), 1e-13 * abs2 + 1e-300) << "p " << p << " x " << x;
    }
  }
}

// The textbook recursion N_{j,0} = [t_j <= x < t_{j+1}], N_{j,p} = (x - t_j) / (t_{j+p} - t_j)
// N_{j,p-1} + (t_{j+p+1} - x) / (t_{j+p+1} - t_{j+1}) N_{j+1,p-1} (0/0 = 0), on the clamped knots,
// with the last interval closed at the upper end: an independent reference for the basis values.
double recursive_basis(const std::vector<double>& t, int j, int p, double x, double upper) {
  if (p == 0) {
    if (x >= t[static_cast<size_t>(j)] && x < t[static_cast<size_t>(j) + 1]) return 1.0;
    // x = upper belongs to the last non-empty interval.
    return x == upper && t[static_cast<size_t>(j)] < upper && t[static_cast<size_t>(j) + 1] == upper ? 1.0 : 0.0;
  }
  const double tj = t[static_cast<size_t>(j)], tjp = t[static_cast<size_t>(j + p)];
  const double tj1 = t[static_cast<size_t>(j) + 1], tjp1 = t[static_cast<size_t>(j + p) + 1];
  double v = 0.0;
  if (tjp > tj) v += (x - tj) / (tjp - tj) * recursive_basis(t, j, p - 1, x, upper);
  if (tjp1 > tj1) v += (tjp1 - x) / (tjp1 - tj1) * recursive_basis(t, j + 1, p - 1, x, upper);
  return v;
}

// Verifies the stored per-interval (Bernstein) form against the recursive definition above for
// degrees 0..3 on nonuniform breakpoints at 1001 points, the ends included: every function's value
// within 1e-14 (both are sums of a few products of numbers <= 1; the recursion's divisions and the
// Bernstein form's rounding each give a few eps).
TEST(SplineBasis, MatchesTheRecursiveDefinition) {
  for (int p = 0; p <= wrc::kMaxSplineDegree; ++p) {
    const wrc::BSplineBasis basis(p, kBreaks);
    const std::vector<double> t = basis.knots();
    for (int s = 0; s <= 1000; ++s) {
      const double x = s / 1000.0;
      const FullBasis f = full_basis(basis, x);
      for (int j = 0; j < basis.size(); ++j)
        EXPECT_NEAR(f.value[static_cast<size_t>(j)], recursive_basis(t, j, p, x, basis.upper()), 1e-14)
            << "p " << p << " x " << x << " N" << j;
    }
  }
}

// Verifies interval(): b_i <= x < b_{i+1}, the last interval at the upper end, the end intervals
// outside; and that the value-only evaluation equals the full one bit for bit.
TEST(SplineBasis, IntervalSearch) {
  const wrc::BSplineBasis basis(3, kBreaks);
  EXPECT_EQ(basis.interval(-5.0), 0);
  EXPECT_EQ(basis.interval(0.0), 0);
  EXPECT_EQ(basis.interval(0.1), 1);
  EXPECT_EQ(basis.interval(0.39), 2);
  EXPECT_EQ(basis.interval(0.4), 3);
  EXPECT_EQ(basis.interval(1.0), 4);
  EXPECT_EQ(basis.interval(7.0), 4);
  double v[4], w[4], d1[4], d2[4];
  basis.evaluate(0.37, v, nullptr, nullptr);
  basis.evaluate(0.37, w, d1, d2);
  for (int r = 0; r < 4; ++r) EXPECT_EQ(v[r], w[r]);
}

// Verifies the first derivative against the central difference of the values and the second
// against the central difference of the first, for degrees 1..3 at points at least 2h inside an
// interval (one polynomial piece). The tolerance is central_difference_tolerance() with the
// derivative bounds above: the second-derivative difference has no truncation (N''' is constant on
// a piece of degree <= 3), the first-derivative one h^2/6 |N'''|.
TEST(SplineBasis, DerivativesMatchFiniteDifferences) {
  const double h = 1e-6;
  for (int p = 1; p <= wrc::kMaxSplineDegree; ++p) {
    const wrc::BSplineBasis basis(p, kBreaks);
    for (int s = 1; s < 1000; ++s) {
      const double x = s / 1000.0;
      const int i = basis.interval(x);
      if (x - kBreaks[static_cast<size_t>(i)] < 2 * h || kBreaks[static_cast<size_t>(i) + 1] - x < 2 * h) continue;
      const FullBasis c = full_basis(basis, x), plus = full_basis(basis, x + h), minus = full_basis(basis, x - h);
      const double tol1 = central_difference_tolerance(h, derivative_bound(basis, 3), 1.0 + derivative_bound(basis, 1) * h);
      const double tol2 = central_difference_tolerance(h, derivative_bound(basis, 4),
                                                       derivative_bound(basis, 1) + derivative_bound(basis, 2) * h);
      for (int r = 0; r < basis.size(); ++r) {
        const size_t rs = static_cast<size_t>(r);
        EXPECT_NEAR(c.d1[rs], (plus.value[rs] - minus.value[rs]) / (2 * h), tol1) << "p " << p << " x " << x << " N" << r;
        EXPECT_NEAR(c.d2[rs], (plus.d1[rs] - minus.d1[rs]) / (2 * h), tol2) << "p " << p << " x " << x << " N" << r;
      }
    }
  }
}

// Verifies smoothness across every interior breakpoint b: the left and right limits, taken at
// b -/+ eps (eps = 1e-9), of each function's derivatives of order < degree agree within
// 2 eps max|N^(k+1)| (the pieces move by at most that over eps) plus rounding; the degree-th
// derivative (degree 1: N', degree 2: N'') jumps by more than 1 for some function, the spline being
// exactly C^(degree-1). Also the right limit equals the evaluation at b (x = b belongs to the right
// piece) to the same tolerance.
TEST(SplineBasis, ContinuityAcrossBreakpoints) {
  const double eps = 1e-9;
  for (int p = 1; p <= wrc::kMaxSplineDegree; ++p) {
    const wrc::BSplineBasis basis(p, kBreaks);
    for (size_t j = 1; j + 1 < kBreaks.size(); ++j) {
      const double b = kBreaks[j];
      const FullBasis left = full_basis(basis, b - eps), right = full_basis(basis, b + eps), at = full_basis(basis, b);
      double jump_p = 0;
      for (int r = 0; r < basis.size(); ++r) {
        const size_t rs = static_cast<size_t>(r);
        const std::vector<double>* orders[3] = {&left.value, &left.d1, &left.d2};
        const std::vector<double>* orders_r[3] = {&right.value, &right.d1, &right.d2};
        const std::vector<double>* orders_at[3] = {&at.value, &at.d1, &at.d2};
        for (int k = 0; k < p; ++k) {  // orders 0..p-1 (at most 2: d2 is the highest computed)
          const double l = (*orders[k])[rs], rr = (*orders_r[k])[rs];
          const double tol = 2 * eps * derivative_bound(basis, k + 1) + 16 * kEps * (1 + derivative_bound(basis, k));
          EXPECT_NEAR(l, rr, tol) << "p " << p << " b " << b << " N" << r << " order " << k;
          EXPECT_NEAR((*orders_at[k])[rs], rr, tol) << "p " << p << " b " << b << " N" << r << " order " << k;
        }
        if (p <= 2) jump_p = std::max(jump_p, std::abs((*orders[p])[rs] - (*orders_r[p])[rs]));
      }
      if (p <= 2) {
        EXPECT_GT(jump_p, 1.0) << "p " << p << " b " << b;
      }
    }
  }
}

// Verifies the argument checks name the offending value: degree, too few breakpoints, a breakpoint
// out of order or not finite, and uniform() with no interval or an empty range.
TEST(SplineBasis, RejectsBadArguments) {
  expect_invalid([] { wrc::BSplineBasis(4, {0.0, 1.0}); }, "degree 4 must be in 0..3");
  expect_invalid([] { wrc::BSplineBasis(-1, {0.0, 1.0}); }, "degree -1 must be in 0..3");
  expect_invalid([] { wrc::BSplineBasis(2, {0.0}); }, "at least 2 breakpoints, got 1");
  expect_invalid([] { wrc::BSplineBasis(2, {0.0, 0.5, 0.1, 1.0}); },
                 "breakpoint 2 = 0.1 is not greater than breakpoint 1 = 0.5");
  expect_invalid([] { wrc::BSplineBasis(2, {0.0, 0.5, 0.5}); }, "breakpoint 2 = 0.5 is not greater");
  expect_invalid([] { wrc::BSplineBasis(1, {0.0, std::nan(""), 1.0}); }, "breakpoint 1 = nan is not finite");
  expect_invalid([] { wrc::BSplineBasis::uniform(3, 0.0, 1.0, 0); }, "intervals = 0 must be >= 1");
  expect_invalid([] { wrc::BSplineBasis::uniform(3, 1.0, 1.0, 4); }, "need finite lower < upper, got [1, 1]");
  expect_invalid([] { wrc::TensorBasis(std::vector<wrc::BSplineBasis>{}); }, "0 bases, need 1..4");
  const auto u = wrc::BSplineBasis::uniform(2, -0.01, 0.01, 4);
  EXPECT_EQ(u.breakpoints().size(), 5u);
  EXPECT_DOUBLE_EQ(u.breakpoints()[1], -0.005);
  EXPECT_EQ(u.breakpoints().back(), 0.01);
}

// The 3-D basis of degrees (3, 3, 2) on nonuniform breakpoints used by the tensor tests below.
wrc::TensorBasis example_tensor_basis() {
  return wrc::TensorBasis({wrc::BSplineBasis(3, {0.0, 0.2, 0.3, 0.6, 0.75, 1.0}),
                           wrc::BSplineBasis(3, {-1.0, -0.2, 0.5, 1.1, 2.0}),
                           wrc::BSplineBasis(2, {0.0, 0.1, 0.3, 0.5})});
}

// Verifies the Hessian slot order (upper triangle, row-major) for d = 3 and d = 4 and symmetry in
// (k, l); the flat index of the terms (row-major, last variable fastest, consecutive in the last
// variable); the tensor basis sums to 1 with vanishing gradient and Hessian (products of 1-D
// partitions of unity; tolerance as in the 1-D test, times the 1-D derivative bounds).
TEST(SplineTensor, SlotsIndicesAndPartitionOfUnity) {
  const int expected3[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) EXPECT_EQ(wrc::hessian_slot(k, l, 3), expected3[k][l]);
  EXPECT_EQ(wrc::hessian_slot(1, 1, 4), 4);
  EXPECT_EQ(wrc::hessian_slot(2, 3, 4), 8);
  EXPECT_EQ(wrc::hessian_slot(3, 3, 4), 9);

  const wrc::TensorBasis basis = example_tensor_basis();
  EXPECT_EQ(basis.size(), 8 * 7 * 5);
  wrc::TensorBasisPoint point;
  const double x[3] = {0.65, 0.7, 0.2};  // intervals 3, 2, 1
  basis.evaluate(x, wrc::SplineDerivatives::kHessian, point);
  ASSERT_EQ(point.terms, 4 * 4 * 3);
  EXPECT_EQ(point.dimension, 3);
  EXPECT_EQ(point.index[0], (3 * 7 + 2) * 5 + 1);
  EXPECT_EQ(point.index[1], point.index[0] + 1);
  EXPECT_EQ(point.index[3], point.index[0] + 5);      // next roll index
  EXPECT_EQ(point.index[12], point.index[0] + 7 * 5); // next y index
  EXPECT_TRUE(basis.contains(x));
  const double outside[3] = {0.5, 2.01, 0.2};
  EXPECT_FALSE(basis.contains(outside));

  double sum = 0, gradient[3] = {}, hessian[6] = {};
  for (int t = 0; t < point.terms; ++t) {
    const size_t ts = static_cast<size_t>(t);
    sum += point.value[ts];
    for (int k = 0; k < 3; ++k) gradient[k] += point.gradient[static_cast<size_t>(k)][ts];
    for (int s = 0; s < 6; ++s) hessian[s] += point.hessian[static_cast<size_t>(s)][ts];
  }
  EXPECT_NEAR(sum, 1.0, 64 * kEps);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(gradient[k], 0.0, 1e-13 * derivative_bound(basis.basis(k), 1));
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) {
      std::vector<int> alpha(3, 0);
      ++alpha[static_cast<size_t>(k)];
      ++alpha[static_cast<size_t>(l)];
      EXPECT_NEAR(hessian[wrc::hessian_slot(k, l, 3)], 0.0, 1e-13 * derivative_bound(basis, alpha));
    }
}

// Verifies the tensor set's values, gradients and Hessians (all slots, mixed ones included) for 5
// functions with random coefficients in [-1, 1]: gradient of each function against the central
// difference of values(), Hessian entry (k, l) against the central difference along l of the
// analytic gradient k (gradients() of all functions), at 200 random points at least 2h inside a
// cell. Tolerances from central_difference_tolerance() with the tensor derivative bounds; also
// derivatives() agrees with values() and gradients() to rounding, and kGradient evaluation gives the
// same gradient as kHessian.
TEST(SplineTensor, GradientAndHessianMatchFiniteDifferences) {
  const wrc::TensorBasis basis = example_tensor_basis();
  const int m = 5;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::MatrixXd c(basis.size(), m);
  for (Eigen::Index i = 0; i < c.size(); ++i) c.data()[i] = unit(rng);
  const wrc::TensorSplineSet set(basis, c);
  EXPECT_EQ(set.functions(), m);
  EXPECT_EQ(set.coefficients(), c);
  EXPECT_EQ(set.coefficient(17, 3), c(17, 3));

  const double h = 1e-5;
  wrc::TensorBasisPoint point, shifted, gradient_only;
  int checked = 0;
  while (checked < 200) {
    double x[3];
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
      const auto& b = basis.basis(k);
      x[k] = b.lower() + (b.upper() - b.lower()) * 0.5 * (unit(rng) + 1.0);
      const int i = b.interval(x[k]);
      inside = inside && x[k] - b.breakpoints()[static_cast<size_t>(i)] > 2 * h &&
               b.breakpoints()[static_cast<size_t>(i) + 1] - x[k] > 2 * h;
    }
    if (!inside) continue;
    ++checked;
    basis.evaluate(x, wrc::SplineDerivatives::kHessian, point);
    double values[m], gradients[3 * m];
    set.values(point, values);
    set.gradients(point, gradients);
    basis.evaluate(x, wrc::SplineDerivatives::kGradient, gradient_only);
    double gradients_g[3 * m];
    set.gradients(gradient_only, gradients_g);
    for (int j = 0; j < m; ++j) {
      double value, gradient[3], hessian[6];
      set.derivatives(point, j, value, gradient, hessian);
      EXPECT_NEAR(value, values[j], 1e-14 * 64);
      for (int k = 0; k < 3; ++k) {
        const double scale = derivative_bound(basis, {k == 0, k == 1, k == 2});
        EXPECT_NEAR(gradient[k], gradients[k * m + j], 1e-14 * 64 * scale);
        EXPECT_EQ(gradients_g[k * m + j], gradients[k * m + j]);
      }
      for (int l = 0; l < 3; ++l) {
        double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
        xp[l] += h;
        xm[l] -= h;
        double vp[m], vm[m], gp[3 * m], gm[3 * m];
        basis.evaluate(xp, wrc::SplineDerivatives::kGradient, shifted);
        set.values(shifted, vp);
        set.gradients(shifted, gp);
        basis.evaluate(xm, wrc::SplineDerivatives::kGradient, shifted);
        set.values(shifted, vm);
        set.gradients(shifted, gm);
        std::vector<int> third(3, 0), one(3, 0);
        third[static_cast<size_t>(l)] = 3;
        one[static_cast<size_t>(l)] = 1;
        const double tol_g = central_difference_tolerance(h, derivative_bound(basis, third), 1.0 + derivative_bound(basis, one) * h);
        EXPECT_NEAR(gradient[l], (vp[j] - vm[j]) / (2 * h), tol_g) << "function " << j << " variable " << l;
        for (int k = 0; k < 3; ++k) {
          std::vector<int> alpha = third, beta = one;
          ++alpha[static_cast<size_t>(k)];
          ++beta[static_cast<size_t>(k)];
          std::vector<int> gk(3, 0);
          gk[static_cast<size_t>(k)] = 1;
          const double tol_h = central_difference_tolerance(
              h, derivative_bound(basis, alpha), derivative_bound(basis, gk) + derivative_bound(basis, beta) * h);
          EXPECT_NEAR(hessian[wrc::hessian_slot(k, l, 3)], (gp[k * m + j] - gm[k * m + j]) / (2 * h), tol_h)
              << "function " << j << " d2/dv" << k << "dv" << l;
        }
      }
    }
  }
}

}  // namespace
