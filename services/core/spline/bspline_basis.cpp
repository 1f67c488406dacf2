/// @file
/// B-spline basis on clamped knots. At construction the Cox-de Boor triangle (Piegl & Tiller, The
/// NURBS Book, algorithm A2.3) gives each interval's degree + 1 non-zero functions as polynomials;
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

#include "core/numerics/simd_clones.hpp"

namespace wrc {
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("BSplineBasis: " + message); }

// Construction only (the pieces' Bernstein coefficients). Basis functions N_{i..i+P} of degree P on
// interval i of breakpoints b (m + 1 values) at x, and derivatives up to order `orders` (0..2) into
// d1 / d2. The knot t_j of the clamped sequence is
// b[clamp(j - P, 0, m)], so the knot vector is never materialised. inverse holds this interval's
// reciprocal knot differences inv(j, r) = 1 / (t_{span+r+1} - t_{span+1-j+r}), r < j <= P.
// Derivatives from the lower-degree functions of the same triangle:
//   N'_{k,j} = j (N_{k,j-1} / (t_{k+j} - t_k) - N_{k+1,j-1} / (t_{k+j+1} - t_{k+1})),
// applied once for d1 and twice for d2 (no division, a few dozen operations for cubics).
template <int P>
void evaluate_degree(const double* b, int m, int i, const double* inverse, double x, int orders, double* value,
                     double* d1, double* d2) {
  auto knot = [b, m](int j) { return b[std::clamp(j - P, 0, m)]; };
  auto inv = [inverse](int j, int r) { return inverse[j * (P + 1) + r]; };
  const int span = i + P;  // index of the knot interval in the full knot sequence
  // ndu[r][j], r <= j: the degree-j functions N_{span-j+r, j} (the Cox-de Boor triangle).
  double ndu[P + 1][P + 1];
  double left[P + 1], right[P + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= P; ++j) {
    left[j] = x - knot(span + 1 - j);
    right[j] = knot(span + j) - x;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = ndu[r][j - 1] * inv(j, r);
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int r = 0; r <= P; ++r) value[r] = ndu[r][P];
  if (orders == 0) return;
  // out[r] = j (lower[r-1] inv(j, r-1) - lower[r] inv(j, r)), r = 0..j: the derivative of the
  // degree-j functions from the j coefficients `lower` of degree j - 1.
  auto raise = [&inv](int j, const double* lower, double* out) {
    for (int r = 0; r <= j; ++r) {
      double v = 0.0;
      if (r >= 1) v += lower[r - 1] * inv(j, r - 1);
      if (r <= j - 1) v -= lower[r] * inv(j, r);
      out[r] = j * v;
    }
  };
  double lower[P + 1], middle[P + 1];
  if constexpr (P == 0) {
    d1[0] = 0.0;
  } else {
    for (int r = 0; r < P; ++r) lower[r] = ndu[r][P - 1];
    raise(P, lower, d1);
  }
  if (orders < 2) return;
  if constexpr (P < 2) {
    for (int r = 0; r <= P; ++r) d2[r] = 0.0;
  } else {
    for (int r = 0; r < P - 1; ++r) lower[r] = ndu[r][P - 2];
    raise(P - 1, lower, middle);  // first derivatives of the degree P - 1 functions
    raise(P, middle, d2);
  }
}

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
  // Reciprocal knot differences per interval i: inverse[j][r] = 1 / (t_{i+P+r+1} - t_{i+P+1-j+r})
  // for r < j <= P, the divisors of the Cox-de Boor triangle (the knots do not depend on x).
  const int P = degree_, m = intervals();
  auto knot = [this, P, m](int j) { return breakpoints_[static_cast<size_t>(std::clamp(j - P, 0, m))]; };
  std::vector<double> inverse(static_cast<size_t>(P + 1) * (P + 1), 0.0);
  pieces_.assign(static_cast<size_t>(m) * kPieceSize, 0.0);
  inverse_widths_.resize(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) {
    const int span = i + P;
    for (int j = 1; j <= P; ++j)
      for (int r = 0; r < j; ++r)
        inverse[static_cast<size_t>(j * (P + 1) + r)] = 1.0 / (knot(span + r + 1) - knot(span + 1 - j + r));
    // The piece's functions and first derivatives at both ends of the interval (x1 within this
    // piece), from the triangle.
    const double x0 = breakpoints_[static_cast<size_t>(i)], x1 = breakpoints_[static_cast<size_t>(i) + 1];
    const double h = x1 - x0;
    double v0[kMaxSplineDegree + 1], d0[kMaxSplineDegree + 1], v1[kMaxSplineDegree + 1], d1[kMaxSplineDegree + 1];
    double unused[kMaxSplineDegree + 1];
    switch (P) {
      case 0: evaluate_degree<0>(breakpoints_.data(), m, i, inverse.data(), x0, 1, v0, d0, unused);
              evaluate_degree<0>(breakpoints_.data(), m, i, inverse.data(), x1, 1, v1, d1, unused); break;
      case 1: evaluate_degree<1>(breakpoints_.data(), m, i, inverse.data(), x0, 1, v0, d0, unused);
              evaluate_degree<1>(breakpoints_.data(), m, i, inverse.data(), x1, 1, v1, d1, unused); break;
      case 2: evaluate_degree<2>(breakpoints_.data(), m, i, inverse.data(), x0, 1, v0, d0, unused);
              evaluate_degree<2>(breakpoints_.data(), m, i, inverse.data(), x1, 1, v1, d1, unused); break;
      default: evaluate_degree<3>(breakpoints_.data(), m, i, inverse.data(), x0, 1, v0, d0, unused);
               evaluate_degree<3>(breakpoints_.data(), m, i, inverse.data(), x1, 1, v1, d1, unused); break;
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
