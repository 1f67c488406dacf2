// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/cubic_spline.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/numerics/tridiagonal.hpp"

namespace wrc {
namespace {

// Second derivative of the parabola through three points.
double parabola_second_derivative(double x0, double y0, double x1, double y1, double x2, double y2) {
  const double d01 = (y1 - y0) / (x1 - x0);
  const double d12 = (y2 - y1) / (x2 - x1);
  return 2.0 * (d12 - d01) / (x2 - x0);
}

}  // namespace

CubicSpline::CubicSpline(std::vector<double> x, const std::vector<double>& y) : x_(std::move(x)) {
  const std::size_t n = x_.size();
  if (y.size() != n || n < 3) {
    throw std::invalid_argument("cubic spline: need at least 3 knots and as many values");
  }
  for (std::size_t i = 1; i < n; ++i) {
    if (!(x_[i] > x_[i - 1])) {
      throw std::invalid_argument("cubic spline: knots must be strictly increasing");
    }
  }
  // Second derivatives m_i: m_0 and m_{n-1} given, interior rows i = 1..n-2
  // h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (d_i - d_{i-1}), a tridiagonal system.
  std::vector<double> m(n, 0.0);
  m[0] = parabola_second_derivative(x_[0], y[0], x_[1], y[1], x_[2], y[2]);
  m[n - 1] = parabola_second_derivative(x_[n - 3], y[n - 3], x_[n - 2], y[n - 2], x_[n - 1],
                                        y[n - 1]);
  const std::size_t unknowns = n - 2;  // m_1 .. m_{n-2}
  std::vector<double> lower(unknowns), diag(unknowns), upper(unknowns), rhs(unknowns);
  for (std::size_t j = 0; j < unknowns; ++j) {
    const std::size_t i = j + 1;
    const double h0 = x_[i] - x_[i - 1];
    const double h1 = x_[i + 1] - x_[i];
    lower[j] = h0;
    diag[j] = 2.0 * (h0 + h1);
    upper[j] = h1;
    rhs[j] = 6.0 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
    if (j == 0) rhs[j] -= h0 * m[0];
    if (j == unknowns - 1) rhs[j] -= h1 * m[n - 1];
  }
  const std::vector<double> interior = solve_tridiagonal(lower, std::move(diag), upper, std::move(rhs));
  std::copy(interior.begin(), interior.end(), m.begin() + 1);
  coefficients_.resize(4 * (n - 1));
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = x_[i + 1] - x_[i];
    double* c = &coefficients_[4 * i];
    c[0] = y[i];
    c[1] = (y[i + 1] - y[i]) / h - h * (2.0 * m[i] + m[i + 1]) / 6.0;
    c[2] = 0.5 * m[i];
    c[3] = (m[i + 1] - m[i]) / (6.0 * h);
  }
  lookup_ = IntervalLookup(x_);
}

SplineSample CubicSpline::evaluate(double x) const {
  const std::size_t i = lookup_.find(x_, x);
  const double* c = &coefficients_[4 * i];
  const double t = x - x_[i];
  return {c[0] + t * (c[1] + t * (c[2] + t * c[3])), c[1] + t * (2.0 * c[2] + t * 3.0 * c[3]),
          2.0 * c[2] + 6.0 * c[3] * t};
}

}  // namespace wrc
