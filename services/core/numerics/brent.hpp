// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Brent's method for a root of a continuous function inside a sign-changing bracket.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace wrc {

/// Result of a bracketed root search. When converged is false the iterations ran out before the
/// bracket shrank to the tolerance: x is only the best iterate so far, somewhere in
/// [bracket_low, bracket_high]; the caller must handle that (require_converged() turns it into an
/// exception naming the interval and the iterations).
struct [[nodiscard]] RootResult {
  double x = 0;             ///< the root (the best iterate when not converged)
  double fx = 0;            ///< the function value there
  int evaluations = 0;      ///< function evaluations used (= iterations)
  bool converged = true;    ///< the bracket shrank to the tolerance (or f(x) == 0 exactly)
  double interval_low = 0;  ///< the interval searched, as given (its smaller end) [unit of x]
  double interval_high = 0; ///< the interval searched, as given (its larger end) [unit of x]
  double bracket_low = 0;   ///< the bracket left at the end (smaller end) [unit of x]
  double bracket_high = 0;  ///< the bracket left at the end (larger end) [unit of x]
};

/// Thrown by require_converged() for a root search that ran out of iterations.
class RootNotConvergedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Returns r.x when r converged, else throws RootNotConvergedError:
/// "<what>: Brent's method did not converge in <n> iterations on [lo, hi] (bracket left [c, d])".
inline double require_converged(const RootResult& r, const std::string& what) {
  if (r.converged) return r.x;
  std::ostringstream msg;
  msg.precision(17);
  msg << what << ": Brent's method did not converge in " << r.evaluations << " iterations on ["
      << r.interval_low << ", " << r.interval_high << "] (bracket left [" << r.bracket_low << ", "
      << r.bracket_high << "])";
  throw RootNotConvergedError(msg.str());
}

/// Finds a root of f in [a, b] where f(a) and f(b) have opposite signs (or one is zero), to an
/// absolute tolerance tol in x. fa and fb are the already known values at a and b.
/// Brent (1973): inverse quadratic interpolation with bisection safeguard; never leaves the bracket.
/// After max_iterations evaluations without reaching the tolerance the result has converged =
/// false (never silently: every caller checks it).
template <class F>
RootResult brent_root(F&& f, double a, double b, double fa, double fb, double tol, int max_iterations = 100) {
  const double low = std::min(a, b), high = std::max(a, b);
  if (fa == 0) return {a, fa, 0, true, low, high, a, a};
  if (fb == 0) return {b, fb, 0, true, low, high, b, b};
  if ((fa > 0) == (fb > 0)) throw std::invalid_argument("brent_root: the interval does not bracket a root");
  double c = a, fc = fa, d = b - a, e = d;
  int evaluations = 0;
  for (int iter = 0; iter < max_iterations; ++iter) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::fabs(fc) < std::fabs(fb)) {
      a = b; b = c; c = a;
      fa = fb; fb = fc; fc = fa;
    }
    const double tol1 = 2 * 1e-16 * std::fabs(b) + 0.5 * tol;
    const double xm = 0.5 * (c - b);
    if (std::fabs(xm) <= tol1 || fb == 0) {
      return {b, fb, evaluations, true, low, high, std::min(b, c), std::max(b, c)};
    }
    if (std::fabs(e) >= tol1 && std::fabs(fa) > std::fabs(fb)) {
      double p, q, r;
      const double s = fb / fa;
      if (a == c) {
        p = 2 * xm * s;
        q = 1 - s;
      } else {
        q = fa / fc;
        r = fb / fc;
        p = s * (2 * xm * q * (q - r) - (b - a) * (r - 1));
        q = (q - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      p = std::fabs(p);
      if (2 * p < std::min(3 * xm * q - std::fabs(tol1 * q), std::fabs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::fabs(d) > tol1 ? d : (xm > 0 ? tol1 : -tol1);
    fb = f(b);
    ++evaluations;
  }
  // Out of iterations: the root lies between b and c whenever f(b) and f(c) differ in sign.
  if ((fb > 0) == (fc > 0)) c = a;
  return {b, fb, evaluations, false, low, high, std::min(b, c), std::max(b, c)};
}

}  // namespace wrc
