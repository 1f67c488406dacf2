// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// An interpolating cubic spline y(x) with precomputed per-interval polynomials (C2).

#include <vector>

#include "core/numerics/interval_lookup.hpp"
#include "core/numerics/spline_sample.hpp"

namespace wrc {

/// Interpolating cubic spline through (x_i, y_i), x strictly increasing, at least 3 knots.
/// End conditions: the second derivative at each end is set to that of the parabola through the
/// three end points (exact for quadratics, and no artificial zero curvature as with natural ends).
/// evaluate() finds the interval through an IntervalLookup, no allocation.
class CubicSpline {
 public:
  /// @param x knots [any length unit], strictly increasing, size >= 3
  /// @param y values at the knots, same size
  /// @throws std::invalid_argument on size mismatch, fewer than 3 knots or non-increasing x.
  CubicSpline(std::vector<double> x, const std::vector<double>& y);

  /// Value, first and second derivative at x; outside [x_0, x_{n-1}] the end polynomials are
  /// extrapolated.
  SplineSample evaluate(double x) const;

  /// The knots.
  const std::vector<double>& knots() const { return x_; }

 private:
  std::vector<double> x_;
  // Interval i: y = a + t (b + t (c + t d)), t = x - x_i; stored as 4 consecutive doubles.
  std::vector<double> coefficients_;
  IntervalLookup lookup_;
};

}  // namespace wrc
