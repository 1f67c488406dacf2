// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Value and first two derivatives of a univariate spline at one point.

namespace wrc {

/// What CubicSpline and NaturalSpline give at one x.
struct SplineSample {
  double value = 0;              ///< y(x) [unit of y]
  double slope = 0;              ///< dy/dx [unit of y / unit of x]
  double second_derivative = 0;  ///< d2y/dx2 [unit of y / unit of x^2]
};

}  // namespace wrc
