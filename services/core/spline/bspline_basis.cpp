// SPDX-License-Identifier: Apache-2.0
/// @file
/// B-spline basis on clamped knots. At construction the Cox-de Boor recursion (core/numerics/
/// bspline_span.hpp) gives each interval's degree + 1 non-zero functions as polynomials;
/// they are stored in Bernstein form, so that an evaluation is a few multiply-adds per function
/// and derivative order (no division, no triangle) with fixed-size local arrays.

#include "core/spline/bspline_basis.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/numerics/bspline_span.hpp"
#include "core/numerics/simd_clones.hpp"

namespace wrc {
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("BSplineBasis: " + message); }

}  // namespace

BSplineBasis::BSplineBasis(int degree, std::vector<double> breakpoints)
    : degree_(degree), breakpoints_(std::move(breakpoints)) {
  if (degree < 0 || degree > kMaxSplineDegree) {
    fail("degree " + std::to_string(degree) + " must be in 0.." + std::to_string(kMaxSplineDegree));
  }
  if (breakpoints_.size() < 2) fail("needs at least 2 breakpoints, got " + std::to_string(breakpoints_.size()));
  for (size_t i = 0; i < breakpoints_.size(); ++i) {
    std::ostringstream msg;
    if (!std::isfinite(breakpoints_[i])) {
      msg << "breakpoint " << i << " = " << breakpoints_[i] << " is not finite";
      fail(msg.str());
    }
    if (i > 0 && !(breakpoints_[i] > breakpoints_[i - 1])) {
      msg << "breakpoint " << i << " = " << breakpoints_[i] << " is not greater than breakpoint " << i - 1
          << " = " << breakpoints_[i - 1];
      fail(msg.str());
    }
  }
  // Per interval, its degree + 1 functions and their first derivatives at both ends (x1 within
  // this piece: the span's polynomials), from the Cox-de Boor recursion on the clamped knots.
  const int P = degree_, m = intervals();
  const std::vector<double> knot_sequence = knots();
  pieces_.assign(static_cast<size_t>(m) * kPieceSize, 0.0);
  inverse_widths_.resize(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    const int span = i + P;
    const double x0 = breakpoints_[static_cast<size_t>(i)], x1 = breakpoints_[static_cast<size_t>(i) + 1];
    const double h = x1 - x0;
    const BSplineSpanTable at0 = bspline_span_derivatives(knot_sequence, P, span, x0);
    const BSplineSpanTable at1 = bspline_span_derivatives(knot_sequence, P, span, x1);
    double v0[kMaxSplineDegree + 1], d0[kMaxSplineDegree + 1], v1[kMaxSplineDegree + 1], d1[kMaxSplineDegree + 1];
    for (int r = 0; r <= P; ++r) {
      v0[r] = at0[0][static_cast<size_t>(r)];
      d0[r] = at0[1][static_cast<size_t>(r)];
      v1[r] = at1[0][static_cast<size_t>(r)];
      d1[r] = at1[1][static_cast<size_t>(r)];
    }
    // Bernstein (Bezier) coefficients of each function on t = (x - x0) / h in [0, 1] from its
    // end values and slopes (a degree-P Bezier curve leaves beta_0 with slope P (beta_1 - beta_0)
    // and reaches beta_P with slope P (beta_P - beta_{P-1}), per unit of t). They are >= 0 (knot
    // insertion turns a B-spline into its Bezier pieces with convex combinations of its
    // non-negative coefficients), so rounding below 0 is set to 0.
    double* piece = pieces_.data() + static_cast<size_t>(i) * kPieceSize;
    double beta[kMaxSplineDegree + 1][kMaxSplineDegree + 1] = {};  // [k][r]
    for (int r = 0; r <= P; ++r) {
      beta[0][r] = v0[r];
      beta[P][r] = v1[r];
      if (P >= 2) {
        beta[1][r] = v0[r] + h * d0[r] / P;
        beta[P - 1][r] = v1[r] - h * d1[r] / P;
      }
      for (int k = 0; k <= P; ++k) beta[k][r] = std::max(0.0, beta[k][r]);
    }
    // Rows: beta_k (k <= P), then the derivative's coefficients P (beta_{k+1} - beta_k) / h
    // (degree P - 1), then the second derivative's P (P - 1) (beta_{k+2} - 2 beta_{k+1} + beta_k) / h^2.
    for (int r = 0; r <= P; ++r) {
      for (int k = 0; k <= P; ++k) piece[k * kLanes + r] = beta[k][r];
      for (int k = 0; k < P; ++k) piece[(kFirstRow + k) * kLanes + r] = P * (beta[k + 1][r] - beta[k][r]) / h;
      for (int k = 0; k + 1 < P; ++k)
        piece[(kSecondRow + k) * kLanes + r] =
            P * (P - 1) * (beta[k + 2][r] - 2.0 * beta[k + 1][r] + beta[k][r]) / (h * h);
    }
    inverse_widths_[static_cast<size_t>(i)] = 1.0 / h;
  }
}

BSplineBasis BSplineBasis::uniform(int degree, double lower, double upper, int intervals) {
  if (intervals < 1) fail("uniform: intervals = " + std::to_string(intervals) + " must be >= 1");
  if (!(lower < upper) || !std::isfinite(lower) || !std::isfinite(upper)) {
    std::ostringstream msg;
    msg << "uniform: need finite lower < upper, got [" << lower << ", " << upper << "]";
    fail(msg.str());
  }
  std::vector<double> b(static_cast<size_t>(intervals) + 1);
  for (int i = 0; i < intervals; ++i) b[static_cast<size_t>(i)] = lower + (upper - lower) * i / intervals;
  b.back() = upper;  // exact end, free of rounding
  return BSplineBasis(degree, std::move(b));
}

std::vector<double> BSplineBasis::knots() const {
  std::vector<double> t;
  t.reserve(static_cast<size_t>(size() + degree_ + 1));
  t.insert(t.end(), static_cast<size_t>(degree_), breakpoints_.front());
  t.insert(t.end(), breakpoints_.begin(), breakpoints_.end());
  t.insert(t.end(), static_cast<size_t>(degree_), breakpoints_.back());
  return t;
}

int BSplineBasis::interval(double x) const {
  const auto it = std::upper_bound(breakpoints_.begin(), breakpoints_.end(), x);
  const int i = static_cast<int>(it - breakpoints_.begin()) - 1;
  return std::clamp(i, 0, intervals() - 1);
}

namespace {

// Bernstein polynomials of degree Q at t (u = 1 - t) into out[0..Q].
template <int Q>
inline void bernstein(double t, double u, double* out) {
  if constexpr (Q == 0) {
    out[0] = 1.0;
  } else if constexpr (Q == 1) {
    out[0] = u, out[1] = t;
  } else if constexpr (Q == 2) {
    out[0] = u * u, out[1] = 2.0 * u * t, out[2] = t * t;
  } else {
    out[0] = u * u * u, out[1] = 3.0 * u * u * t, out[2] = 3.0 * u * t * t, out[3] = t * t * t;
  }
}

// out[r] = sum_k weight[k] * rows[k][r], k <= Q, r <= P (rows of kLanes = 4 doubles). For cubics
// all four lanes at once (GCC vector extension: two SSE2 or one AVX register).
template <int Q, int P>
inline void combine(const double* weight, const double* rows, double* out) {
  if constexpr (P == 3) {
    typedef double Vec4 __attribute__((vector_size(32)));
    Vec4 sum = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k <= Q; ++k) {
      Vec4 row;
      std::memcpy(&row, rows + 4 * k, sizeof row);
      sum += Vec4{weight[k], weight[k], weight[k], weight[k]} * row;
    }
    std::memcpy(out, &sum, sizeof sum);
  } else {
    for (int r = 0; r <= P; ++r) {
      double sum = 0.0;
      for (int k = 0; k <= Q; ++k) sum += weight[k] * rows[4 * k + r];
      out[r] = sum;
    }
  }
}

// The degree-P functions of one piece and their first two derivatives at t from the rows of their
// Bernstein coefficients (values, first derivative, second derivative). Always inlined, so that it
// is compiled for the clone of its caller.
template <int P>
__attribute__((always_inline)) inline void evaluate_piece(const double* value_rows, const double* first_rows,
                                                          const double* second_rows, double t, double* value,
                                                          double* d1, double* d2) {
  const double u = 1.0 - t;
  double w[kMaxSplineDegree + 1];
  bernstein<P>(t, u, w);
  combine<P, P>(w, value_rows, value);
  if (d1) {
    if constexpr (P >= 1) {
      bernstein<P - 1>(t, u, w);
      combine<P - 1, P>(w, first_rows, d1);
    } else {
      d1[0] = 0.0;
    }
  }
  if (d2) {
    if constexpr (P >= 2) {
      bernstein<P - 2>(t, u, w);
      combine<P - 2, P>(w, second_rows, d2);
    } else {
      for (int r = 0; r <= P; ++r) d2[r] = 0.0;
    }
  }
}

}  // namespace

// Cloned for AVX2 and FMA (the combination of each piece's rows, four lanes at a time).
WRC_SIMD_CLONES
int BSplineBasis::evaluate(double x, double* value, double* d1, double* d2) const {
  const int i = interval(x);
  const double t = (x - breakpoints_[static_cast<size_t>(i)]) * inverse_widths_[static_cast<size_t>(i)];
  const double* piece = pieces_.data() + static_cast<size_t>(i) * kPieceSize;
  const double* first = piece + kFirstRow * kLanes;
  const double* second = piece + kSecondRow * kLanes;
  switch (degree_) {
    case 0: evaluate_piece<0>(piece, first, second, t, value, d1, d2); break;
    case 1: evaluate_piece<1>(piece, first, second, t, value, d1, d2); break;
    case 2: evaluate_piece<2>(piece, first, second, t, value, d1, d2); break;
    default: evaluate_piece<3>(piece, first, second, t, value, d1, d2); break;
  }
  return i;
}

}  // namespace wrc
