/// @file
/// B-spline basis on clamped knots: the degree + 1 non-zero functions and their first two
/// derivatives by the Cox-de Boor triangle (Piegl & Tiller, The NURBS Book, algorithm A2.3),
/// unrolled per degree, with fixed-size local arrays (no allocation on the evaluation path).

#include "core/spline/bspline_basis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace wrc {
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("BSplineBasis: " + message); }

// Basis functions N_{i..i+P} of degree P on interval i of breakpoints b (m + 1 values) at x, and
// derivatives up to order `orders` (0..2) into d1 / d2. The knot t_j of the clamped sequence is
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
  inverse_differences_.assign(static_cast<size_t>(m) * (P + 1) * (P + 1), 0.0);
  for (int i = 0; i < m; ++i) {
    const int span = i + P;
    for (int j = 1; j <= P; ++j)
      for (int r = 0; r < j; ++r)
        inverse_differences_[(static_cast<size_t>(i) * (P + 1) + j) * (P + 1) + r] =
            1.0 / (knot(span + r + 1) - knot(span + 1 - j + r));
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

int BSplineBasis::evaluate(double x, double* value, double* d1, double* d2) const {
  const int i = interval(x);
  // Orders wanted: d2 is computed after d1, so a scratch array stands in for a null d1.
  double scratch[kMaxSplineDegree + 1];
  const int orders = d2 ? 2 : d1 ? 1 : 0;
  if (d2 && !d1) d1 = scratch;
  const double* b = breakpoints_.data();
  const int m = intervals();
  const double* inverse = inverse_differences_.data() + static_cast<size_t>(i) * (degree_ + 1) * (degree_ + 1);
  switch (degree_) {
    case 0: evaluate_degree<0>(b, m, i, inverse, x, orders, value, d1, d2); break;
    case 1: evaluate_degree<1>(b, m, i, inverse, x, orders, value, d1, d2); break;
    case 2: evaluate_degree<2>(b, m, i, inverse, x, orders, value, d1, d2); break;
    default: evaluate_degree<3>(b, m, i, inverse, x, orders, value, d1, d2); break;
  }
  return i;
}

}  // namespace wrc
