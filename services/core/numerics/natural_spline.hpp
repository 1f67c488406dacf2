// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The natural interpolating spline of odd degree 2m - 1 (Schoenberg): of all functions through
/// the samples it has the least integral of its squared m-th derivative, it is C^(2m-2) across the
/// samples, and on evenly spaced samples it tends to band-limited (Whittaker-Shannon) interpolation
/// as the degree grows. Used where a sampled signal drives an integrator of high order (track
/// irregularities: docs/track.md), which a cubic spline's jumping third derivative would slow down.

#include <cstddef>
#include <vector>

#include "core/numerics/interval_lookup.hpp"
#include "core/numerics/spline_sample.hpp"

namespace wrc {

/// Largest degree a NaturalSpline takes.
inline constexpr int kMaxNaturalSplineDegree = 9;

/// Interpolating spline of odd degree p = 2m - 1 through (x_i, y_i): a polynomial of degree p on
/// each interval, C^(p-1) at the interior samples, with the natural end conditions (derivatives m
/// to 2m - 2 zero at both ends; a polynomial of degree < m is reproduced exactly). Computed as
/// B-spline coefficients (one sparse banded solve), kept as per-interval Taylor polynomials.
class NaturalSpline {
 public:
  /// @param degree 1, 3, 5, ... up to kMaxNaturalSplineDegree.
  /// @param x samples [any length unit], strictly increasing and finite, at least (degree + 1) / 2
  ///        and at least 2.
  /// @param y values at the samples [any unit], same size, finite.
  /// @throws std::invalid_argument naming the bad degree, count, sample or value.
  NaturalSpline(int degree, std::vector<double> x, const std::vector<double>& y);

  /// Value, first and second derivative at x [unit of y / unit of x^k]; outside [x_0, x_{n-1}] the
  /// end polynomials are extrapolated.
  SplineSample evaluate(double x) const;

  /// The k-th derivative at x, k = 0..degree() [unit of y / unit of x^k] (slower than evaluate()).
  double derivative(int k, double x) const;

  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return x_; }

 private:
  int degree_;
  std::vector<double> x_;
  // Interval i: y = sum_k a_k t^k, t = x - x_i, k = 0..degree; degree + 1 consecutive doubles.
  std::vector<double> taylor_;
  IntervalLookup lookup_;
};

}  // namespace wrc
