#pragma once
/// @file
/// An interpolating cubic spline y(x) with precomputed per-interval polynomials (C2).

#include <vector>


namespace wrc {

/// Value and derivatives of a CubicSpline at one x.
struct CubicSplineSample {
  double value = 0;              ///< y(x) [unit of y]
  double slope = 0;              ///< dy/dx [unit of y / unit of x]
  double second_derivative = 0;  ///< d2y/dx2 [unit of y / unit of x^2]
};

/// Interpolating cubic spline through (x_i, y_i), x strictly increasing, at least 3 knots.
/// End conditions: the second derivative at each end is set to that of the parabola through the
/// three end points (exact for quadratics, and no artificial zero curvature as with natural ends).
/// evaluate() finds the interval by direct indexing into a uniform cell table (4 cells per knot)
/// plus a short forward scan, no allocation.
class CubicSpline {
 public:
  /// @param x knots [any length unit], strictly increasing, size >= 3
  /// @param y values at the knots, same size
  /// @throws std::invalid_argument on size mismatch, fewer than 3 knots or non-increasing x.
  CubicSpline(std::vector<double> x, const std::vector<double>& y);

  /// Value, first and second derivative at x; outside [x_0, x_{n-1}] the end polynomials are
  /// extrapolated.
  CubicSplineSample evaluate(double x) const;

  /// The knots.
  const std::vector<double>& knots() const { return x_; }

 private:
  std::vector<double> x_;
  // Interval i: y = a + t (b + t (c + t d)), t = x - x_i; stored as 4 consecutive doubles.
  std::vector<double> coefficients_;
  // Interval lookup: cell k = floor((x - x_0) * cell_scale_) starts at interval cell_start_[k].
  double cell_scale_ = 0;
  std::vector<unsigned> cell_start_;
};

}  // namespace wrc
