// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/natural_spline.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "core/numerics/bspline_span.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

using DerivativeTable = BSplineSpanTable;
static_assert(kMaxNaturalSplineDegree <= kMaxBSplineSpanDegree, "the span's table holds every degree");

std::string sample_text(std::size_t i, double x) {
  return "sample " + std::to_string(i) + " (x = " + number_text(x) + ")";
}

}  // namespace

NaturalSpline::NaturalSpline(int degree, std::vector<double> x, const std::vector<double>& y)
    : degree_(degree), x_(std::move(x)) {
  if (degree < 1 || degree > kMaxNaturalSplineDegree || degree % 2 == 0)
    throw std::invalid_argument("natural spline: degree " + std::to_string(degree) + " is not odd in 1.." +
                                std::to_string(kMaxNaturalSplineDegree));
  const int m = (degree + 1) / 2;
  const std::size_t n = x_.size();
  const std::size_t least = std::max<std::size_t>(2, static_cast<std::size_t>(m));
  if (n < least)
    throw std::invalid_argument("natural spline: " + std::to_string(n) + " samples, degree " +
                                std::to_string(degree) + " needs at least " + std::to_string(least));
  if (y.size() != n)
    throw std::invalid_argument("natural spline: " + std::to_string(y.size()) + " values for " + std::to_string(n) +
                                " samples");
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x_[i]) || (i > 0 && !(x_[i] > x_[i - 1])))
      throw std::invalid_argument("natural spline: " + sample_text(i, x_[i]) +
                                  " is not finite or not above the one before");
    if (!std::isfinite(y[i]))
      throw std::invalid_argument("natural spline: " + sample_text(i, x_[i]) + ": value " + number_text(y[i]) +
                                  " is not finite");
  }
  const int p = degree;
  // Knots: x_0 and x_{n-1} p + 1 times, the interior samples once; n + p - 1 B-splines. Interval i
  // of the samples is knot span i + p.
  std::vector<double> knots(static_cast<std::size_t>(p), x_.front());
  knots.insert(knots.end(), x_.begin(), x_.end());
  knots.insert(knots.end(), static_cast<std::size_t>(p), x_.back());
  const int intervals = static_cast<int>(n) - 1;
  const int unknowns = static_cast<int>(n) + p - 1;
  std::vector<DerivativeTable> at_sample(n);
  for (int i = 0; i <= intervals; ++i) {
    const int span = std::min(i, intervals - 1) + p;
    at_sample[static_cast<std::size_t>(i)] = bspline_span_derivatives(knots, p, span, x_[static_cast<std::size_t>(i)]);
  }
  // Rows: the m - 1 conditions at x_0, the n interpolation conditions, the m - 1 at x_{n-1}.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  int row = 0;
  auto add_row = [&](int i, int order) {
    const int first = std::min(i, intervals - 1);  // first non-zero B-spline at x_i
    const DerivativeTable& d = at_sample[static_cast<std::size_t>(i)];
    for (int j = 0; j <= p; ++j)
      if (d[order][j] != 0.0) entries.emplace_back(row, first + j, d[order][j]);
    ++row;
  };
  for (int order = m; order <= 2 * m - 2; ++order) add_row(0, order);
  for (int i = 0; i <= intervals; ++i) {
    rhs(row) = y[static_cast<std::size_t>(i)];
    add_row(i, 0);
  }
  for (int order = m; order <= 2 * m - 2; ++order) add_row(intervals, order);
  Eigen::SparseMatrix<double> a(unknowns, unknowns);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success)
    throw std::invalid_argument("natural spline: the interpolation system is singular (" + lu.lastErrorMessage() + ")");
  const Eigen::VectorXd c = lu.solve(rhs);
  // Taylor coefficients at the start of each interval: f^(k)(x_i) / k!.
  taylor_.resize(static_cast<std::size_t>(intervals) * static_cast<std::size_t>(p + 1));
  for (int i = 0; i < intervals; ++i) {
    const DerivativeTable d = bspline_span_derivatives(knots, p, i + p, x_[static_cast<std::size_t>(i)]);
    double factorial = 1.0;
    for (int k = 0; k <= p; ++k) {
      if (k > 0) factorial *= k;
      double f = 0.0;
      for (int j = 0; j <= p; ++j) f += d[k][j] * c(i + j);
      taylor_[static_cast<std::size_t>(i) * static_cast<std::size_t>(p + 1) + static_cast<std::size_t>(k)] =
          f / factorial;
    }
  }
  for (double v : taylor_)
    if (!std::isfinite(v)) throw std::invalid_argument("natural spline: the interpolation system is singular");
  lookup_ = IntervalLookup(x_);
}

SplineSample NaturalSpline::evaluate(double x) const {
  const std::size_t i = lookup_.find(x_, x);
  const double* a = &taylor_[i * static_cast<std::size_t>(degree_ + 1)];
  const double t = x - x_[i];
  double value = a[degree_], slope = 0.0, second = 0.0;
  for (int k = degree_ - 1; k >= 0; --k) {  // Horner for the polynomial and its first two derivatives
    second = second * t + 2.0 * slope;
    slope = slope * t + value;
    value = value * t + a[k];
  }
  return {value, slope, second};
}

double NaturalSpline::derivative(int k, double x) const {
  if (k < 0 || k > degree_)
    throw std::invalid_argument("natural spline: no derivative of order " + std::to_string(k));
  const std::size_t i = lookup_.find(x_, x);
  const double* a = &taylor_[i * static_cast<std::size_t>(degree_ + 1)];
  const double t = x - x_[i];
  // d^k/dt^k sum_j a_j t^j = sum_{j>=k} a_j j! / (j-k)! t^(j-k)
  double sum = 0.0;
  for (int j = degree_; j >= k; --j) {
    double falling = 1.0;
    for (int r = 0; r < k; ++r) falling *= j - r;
    sum = sum * t + a[j] * falling;
  }
  return sum;
}

}  // namespace wrc
