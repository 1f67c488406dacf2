// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A univariate B-spline basis of selectable degree on user-placed or uniform breakpoints, with
/// (degree + 1)-fold end knots (the spline is a polynomial of that degree on every interval
/// between breakpoints and C^(degree-1) across interior breakpoints).

#include <vector>

namespace wrc {

/// Largest degree a BSplineBasis supports (cubic). Degree 0..3.
constexpr int kMaxSplineDegree = 3;

/// B-spline basis N_0..N_{n-1}, n = intervals + degree, on breakpoints b_0 < b_1 < ... < b_m
/// (m = intervals). Knot sequence: b_0 repeated degree + 1 times, the interior breakpoints once,
/// b_m repeated degree + 1 times. Units: those of the variable (y [m], roll and yaw [rad]).
class BSplineBasis {
 public:
  /// @param degree polynomial degree, 0..kMaxSplineDegree.
  /// @param breakpoints strictly increasing and finite, at least 2 values [unit of the variable].
  /// @throws std::invalid_argument naming the bad degree or the first breakpoint out of order / not finite.
  BSplineBasis(int degree, std::vector<double> breakpoints);

  /// intervals equal intervals on [lower, upper] (intervals >= 1, lower < upper).
  static BSplineBasis uniform(int degree, double lower, double upper, int intervals);

  int degree() const { return degree_; }
  int intervals() const { return static_cast<int>(breakpoints_.size()) - 1; }
  /// Number of basis functions (= coefficients along this variable): intervals + degree.
  int size() const { return intervals() + degree_; }
  const std::vector<double>& breakpoints() const { return breakpoints_; }
  /// The full knot sequence (size() + degree + 1 values) with the repeated end knots.
  std::vector<double> knots() const;
  double lower() const { return breakpoints_.front(); }
  double upper() const { return breakpoints_.back(); }

  /// Index of the interval holding x: b_i <= x < b_{i+1}, the last interval for x = upper.
  /// x outside [lower, upper] is taken in the first or last interval (polynomial extrapolation).
  int interval(double x) const;

  /// The degree + 1 basis functions that can be non-zero at x: N_first .. N_{first+degree}, with
  /// their first and second derivatives [1/unit, 1/unit^2]. d1 or d2 may be null (not computed).
  /// Arrays hold degree + 1 values. Returns first (= interval(x)).
  int evaluate(double x, double* value, double* d1, double* d2) const;

 private:
  // Per interval, the Bernstein coefficients of its degree + 1 functions (lanes) on
  // t = (x - b_i) / (b_{i+1} - b_i): rows 0..degree the values, kFirstRow.. the first derivative's
  // (degree - 1), kSecondRow.. the second's (degree - 2), in 1 / unit^order.
  static constexpr int kLanes = kMaxSplineDegree + 1;  // 4, as the evaluation's vector code assumes
  static constexpr int kFirstRow = kMaxSplineDegree + 1;
  static constexpr int kSecondRow = kFirstRow + kMaxSplineDegree;
  static constexpr int kPieceSize = (kSecondRow + kMaxSplineDegree - 1) * kLanes;
  int degree_;
  std::vector<double> breakpoints_;
  std::vector<double> pieces_;          // intervals x kPieceSize
  std::vector<double> inverse_widths_;  // 1 / (b_{i+1} - b_i) per interval [1/unit]
};

}  // namespace wrc
