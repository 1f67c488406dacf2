// SPDX-License-Identifier: Apache-2.0
#include "core/profile/s1002.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {
namespace {

// Section boundaries [mm] from the field side to the flange back (docs/profiles.md, "S1002 wheel").
constexpr double kSAB = 32.15796;
constexpr double kSBC = -26.0;
constexpr double kSCD = -35.0;
constexpr double kSDE = -38.426669071;
constexpr double kSEF = -39.764473993;
constexpr double kSFG = -49.662510381;
constexpr double kSGH = -62.764705882;
constexpr double kSLow = -70.0;
constexpr double kSHigh = 60.0;

// Polynomial coefficients in increasing powers of S, signs folded in.
constexpr double kSectionB[9] = {0.0,           -3.358537058e-02, 1.565681624e-03,
                                 -2.810427944e-05, 5.844240864e-08, -1.562379023e-08,
                                 5.309217349e-15,  -5.957839843e-12, 2.646656573e-13};
constexpr double kSectionC[8] = {-4.320221063e+03, -1.038384026e+03, -1.065501873e+02,
                                 -6.051367875,     -2.054332446e-01, -4.169739389e-03,
                                 -4.687195829e-05, -2.252755540e-07};

// Polynomial value, first and second derivative by Horner's scheme.
template <int N>
ProfileSample polynomial(const double (&c)[N], double s) {
  double p = c[N - 1];
  double dp = 0.0;
  double ddp = 0.0;
  for (int k = N - 2; k >= 0; --k) {
    ddp = ddp * s + 2.0 * dp;
    dp = dp * s + p;
    p = p * s + c[k];
  }
  return {p, dp, ddp};
}

// F = a + sign * sqrt(r^2 - (S + c)^2); sign = -1 for the concave root arc, +1 for the others.
ProfileSample arc(double a, double r, double c, double sign, double s) {
  const double x = s + c;
  // Clamp: at the flange back (S = -70) the argument is exactly zero (vertical tangent).
  const double q = std::max(r * r - x * x, 1e-12 * r * r);
  const double root = std::sqrt(q);
  const double inv = 1.0 / root;  // one division: slope -x/root, second derivative -r^2/root^3
  return {a + sign * root, -sign * x * inv, -sign * r * r * inv * inv * inv};
}

}  // namespace

ProfileSample s1002_evaluate_mm(double s) {
  if (s >= kSAB) {
    return {1.364323640 - 0.066666667 * s, -0.066666667, 0.0};
  }
  if (s >= kSBC) {
    return polynomial(kSectionB, s);
  }
  if (s >= kSCD) {
    return polynomial(kSectionC, s);
  }
  if (s >= kSDE) {
    return arc(16.446, 13.0, 26.210665, -1.0, s);
  }
  if (s >= kSEF) {
    return {-93.576667419 - 2.747477419 * s, -2.747477419, 0.0};
  }
  if (s >= kSFG) {
    return arc(8.834924130, 20.0, 58.558326413, 1.0, s);
  }
  if (s >= kSGH) {
    return arc(16.0, 12.0, 55.0, 1.0, s);
  }
  return arc(9.519259302, 20.5, 49.5, 1.0, s);
}

ProfileSample S1002Profile::evaluate(double s) const {
  const ProfileSample mm = s1002_evaluate_mm(s * 1e3);
  return {mm.height * 1e-3, mm.slope, mm.second_derivative * 1e3};
}

double S1002Profile::lower() const { return kSLow * 1e-3; }
double S1002Profile::upper() const { return kSHigh * 1e-3; }

std::vector<double> S1002Profile::breakpoints() const {
  return {kSGH * 1e-3, kSFG * 1e-3, kSEF * 1e-3, kSDE * 1e-3,
          kSCD * 1e-3, kSBC * 1e-3, kSAB * 1e-3};
}

ProfileSide S1002Profile::side() const { return ProfileSide::kWheel; }
std::string S1002Profile::name() const { return "S1002 (analytic)"; }

}  // namespace wrc
