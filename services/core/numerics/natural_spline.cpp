#include "core/numerics/natural_spline.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

constexpr int kMaxOrder = kMaxNaturalSplineDegree + 1;
using DerivativeTable = std::array<std::array<double, kMaxOrder>, kMaxOrder>;

// The p + 1 B-splines of degree p that are non-zero on knot span `span` (knots[span] <= x <
// knots[span + 1]) and their derivatives 0..p at x: d[k][j] = d^k/dx^k N_{span-p+j}(x). Cox-de Boor
// recursion for the values of every degree, then the derivative recursion
// N'_{j,q} = q (N_{j,q-1} / (u_{j+q} - u_j) - N_{j+1,q-1} / (u_{j+q+1} - u_{j+1})) applied k times.
DerivativeTable basis_derivatives(const std::vector<double>& knots, int p, int span, double x) {
  // values[q][j]: the degree-q B-spline N_{span-q+j, q}(x), j = 0..q.
  DerivativeTable values{};
  values[0][0] = 1.0;
  for (int q = 1; q <= p; ++q) {
    for (int j = 0; j <= q; ++j) {
      const int i = span - q + j;  // global index of N_{i,q}
      double v = 0.0;
      if (j > 0) {  // N_{i,q-1} is values[q-1][j-1]
        const double w = knots[i + q] - knots[i];
        if (w > 0) v += (x - knots[i]) / w * values[q - 1][j - 1];
      }
      if (j < q) {  // N_{i+1,q-1} is values[q-1][j]
        const double w = knots[i + q + 1] - knots[i + 1];
        if (w > 0) v += (knots[i + q + 1] - x) / w * values[q - 1][j];
      }
      values[q][j] = v;
    }
  }
  DerivativeTable d{};
  for (int k = 0; k <= p; ++k) {
    // coefficient[j'] of N_{span-(p-k)+j', p-k} in the k-th derivative of each N_{span-p+j, p}.
    for (int j = 0; j <= p; ++j) {
      std::array<double, kMaxOrder> c{};
      c[static_cast<std::size_t>(j)] = 1.0;  // indices relative to span - p, degree p
      int q = p;
      for (int step = 0; step < k; ++step, --q) {
        // d/dx sum_i c_i N_{i,q} = q sum_i (c_i - c_{i-1}) / (u_{i+q} - u_i) N_{i,q-1}
        std::array<double, kMaxOrder> next{};
        for (int r = 0; r <= p; ++r) {
          const int i = span - p + r;
          const double w = knots[i + q] - knots[i];
          const double previous = r > 0 ? c[static_cast<std::size_t>(r - 1)] : 0.0;
          next[static_cast<std::size_t>(r)] = w > 0 ? q * (c[static_cast<std::size_t>(r)] - previous) / w : 0.0;
        }
        c = next;
      }
      // Evaluate sum_r c_r N_{span-p+r, q}(x): the non-zero ones are r = p - q .. p.
      double sum = 0.0;
      for (int r = p - q; r <= p; ++r) sum += c[static_cast<std::size_t>(r)] * values[q][r - (p - q)];
      d[k][j] = sum;
    }
  }
  return d;
}

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
    at_sample[static_cast<std::size_t>(i)] = basis_derivatives(knots, p, span, x_[static_cast<std::size_t>(i)]);
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
    const DerivativeTable d = basis_derivatives(knots, p, i + p, x_[static_cast<std::size_t>(i)]);
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
