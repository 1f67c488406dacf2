#pragma once
/// @file
/// Brent's method for a root of a continuous function inside a sign-changing bracket.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace wrc {

/// Result of a bracketed root search.
struct RootResult {
  double x = 0;        ///< the root
  double fx = 0;       ///< the function value there
  int evaluations = 0; ///< function evaluations used
};

/// Finds a root of f in [a, b] where f(a) and f(b) have opposite signs (or one is zero), to an
/// absolute tolerance tol in x. fa and fb are the already known values at a and b.
/// Brent (1973): inverse quadratic interpolation with bisection safeguard; never leaves the bracket.
template <class F>
RootResult brent_root(F&& f, double a, double b, double fa, double fb, double tol, int max_iterations = 100) {
  if (fa == 0) return {a, fa, 0};
  if (fb == 0) return {b, fb, 0};
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
    if (std::fabs(xm) <= tol1 || fb == 0) return {b, fb, evaluations};
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
  return {b, fb, evaluations};
}

}  // namespace wrc
