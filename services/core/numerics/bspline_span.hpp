// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The B-splines of one knot span and their derivatives at a point (Cox-de Boor), the one
/// implementation for every spline of wrc: NaturalSpline's interpolation (degree up to 9) and
/// BSplineBasis's Bernstein pieces (degree up to 3) are built from it.

#include <array>
#include <vector>

namespace wrc {

/// Largest degree bspline_span_derivatives() supports.
inline constexpr int kMaxBSplineSpanDegree = 9;

/// table[k][j] = d^k/dx^k N_{span-p+j, p}(x) for k, j = 0..p [1/unit^k]; entries beyond p are 0.
using BSplineSpanTable = std::array<std::array<double, kMaxBSplineSpanDegree + 1>, kMaxBSplineSpanDegree + 1>;

/// The p + 1 B-splines of degree p on the knot sequence knots that are non-zero on knot span
/// `span` (knots[span] <= x < knots[span + 1]; x may lie at or beyond its ends, the span's
/// polynomials continued) and their derivatives of order 0..p at x [unit of the knots]: the
/// Cox-de Boor recursion for the values of every degree, then the derivative recursion
/// N'_{j,q} = q (N_{j,q-1} / (u_{j+q} - u_j) - N_{j+1,q-1} / (u_{j+q+1} - u_{j+1})) applied k
/// times (a zero knot difference drops its term). Source: L. Piegl and W. Tiller, The NURBS Book,
/// 2nd ed., chapter 2.
/// @throws std::invalid_argument when p is outside 0..kMaxBSplineSpanDegree or the span leaves
///         the knots (span < p or span + p + 1 >= knots.size()).
BSplineSpanTable bspline_span_derivatives(const std::vector<double>& knots, int p, int span, double x);

}  // namespace wrc
