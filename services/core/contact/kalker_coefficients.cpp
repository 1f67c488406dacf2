// SPDX-License-Identifier: Apache-2.0
#include "core/contact/kalker_coefficients.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kRows = 19;

// Kalker 1990 Table E.3. Row r (0-based) has table parameter s = 0.1 (r + 1): rows 0..9 are
// a/b = 0.1 .. 1.0 (s = a/b), rows 10..18 are b/a = 0.9 .. 0.1 (s = 2 - b/a). Columns: nu = 0, 0.25, 0.5.
constexpr double kC11[kRows][3] = {
    {2.51, 3.31, 4.85}, {2.59, 3.37, 4.81}, {2.68, 3.44, 4.80}, {2.78, 3.53, 4.82}, {2.88, 3.62, 4.83},
    {2.98, 3.72, 4.91}, {3.09, 3.81, 4.97}, {3.19, 3.91, 5.05}, {3.29, 4.01, 5.12}, {3.40, 4.12, 5.20},
    {3.51, 4.22, 5.30}, {3.65, 4.36, 5.42}, {3.82, 4.54, 5.58}, {4.06, 4.78, 5.80}, {4.37, 5.10, 6.11},
    {4.84, 5.57, 6.57}, {5.57, 6.34, 7.34}, {6.96, 7.78, 8.82}, {10.7, 11.7, 12.9}};
constexpr double kC22[kRows][3] = {
    {2.51, 2.52, 2.53}, {2.59, 2.63, 2.66}, {2.68, 2.75, 2.81}, {2.78, 2.88, 2.98}, {2.88, 3.01, 3.14},
    {2.98, 3.14, 3.31}, {3.09, 3.28, 3.48}, {3.19, 3.41, 3.65}, {3.29, 3.54, 3.82}, {3.40, 3.67, 3.98},
    {3.51, 3.81, 4.16}, {3.65, 3.99, 4.39}, {3.82, 4.21, 4.67}, {4.06, 4.50, 5.04}, {4.37, 4.90, 5.56},
    {4.84, 5.48, 6.31}, {5.57, 6.40, 7.51}, {6.96, 8.14, 9.79}, {10.7, 12.8, 16.0}};
// C23(a/b = 0.8, nu = 0.25) is 1.25 (not the 1.15 of an older CONTACT utility), see
// docs/contact-mechanics.md, "Kalker's linear theory and coefficients".
constexpr double kC23[kRows][3] = {
    {0.334, 0.473, 0.731}, {0.483, 0.603, 0.809}, {0.607, 0.715, 0.889}, {0.720, 0.823, 0.977},
    {0.827, 0.929, 1.07},  {0.930, 1.03, 1.18},   {1.03, 1.14, 1.29},    {1.13, 1.25, 1.40},
    {1.23, 1.36, 1.51},    {1.33, 1.47, 1.63},    {1.44, 1.59, 1.77},    {1.58, 1.75, 1.94},
    {1.76, 1.95, 2.18},    {2.01, 2.23, 2.50},    {2.35, 2.62, 2.96},    {2.88, 3.24, 3.70},
    {3.79, 4.32, 5.01},    {5.72, 6.63, 7.89},    {12.2, 14.6, 18.0}};
// C33: lower confidence (unverified).
constexpr double kC33[kRows][3] = {
    {6.42, 8.28, 11.7},    {3.46, 4.27, 5.66},    {2.49, 2.96, 3.72},    {2.02, 2.32, 2.77},
    {1.74, 1.93, 2.22},    {1.56, 1.68, 1.86},    {1.43, 1.50, 1.60},    {1.34, 1.37, 1.42},
    {1.27, 1.27, 1.27},    {1.21, 1.19, 1.16},    {1.16, 1.11, 1.06},    {1.10, 1.04, 0.954},
    {1.05, 0.965, 0.852},  {1.01, 0.892, 0.751},  {0.958, 0.819, 0.650}, {0.912, 0.747, 0.549},
    {0.868, 0.674, 0.446}, {0.828, 0.601, 0.341}, {0.795, 0.526, 0.228}};

constexpr double kNuColumns[3] = {0.0, 0.25, 0.5};

// Kalker's C23 asymptote for a/b = g -> 0 at Poisson's ratio nu.
double c23_asymptote(double g, double nu) {
  return kPi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0));
}

// One coefficient at one table column (nu index col), for table parameter s in (0, 2).
// which: 0 = C11, 1 = C22, 2 = C23, 3 = C33.
double column_value(const double (&table)[kRows][3], int which, double s, int col) {
  const double nu = kNuColumns[col];
  if (s < 0.1) {
    // a < b side beyond the table: Kalker's g -> 0 asymptotes joined to the g = 0.1 row.
    const double g = s;
    const double row = table[0][col];
    switch (which) {
      case 0: {
        const double limit = kPi * kPi / (4.0 * (1.0 - nu));
        return limit + (row - limit) * g / 0.1;
      }
      case 1: {
        const double limit = kPi * kPi / 4.0;
        return limit + (row - limit) * g / 0.1;
      }
      case 2:
        return row * c23_asymptote(g, nu) / c23_asymptote(0.1, nu);
      default:
        return row * 0.1 / g;  // C33 ~ pi^2 / (16 (1 - nu) g)
    }
  }
  if (s > 1.9) {
    // a > b side beyond the table: log-log extrapolation of the last interval (b/a = 0.2 -> 0.1).
    const double g = 2.0 - s;  // b/a
    const double p = std::log(table[kRows - 1][col] / table[kRows - 2][col]) / std::log(0.5);
    return table[kRows - 1][col] * std::pow(g / 0.1, p);
  }
  const double x = s / 0.1 - 1.0;  // fractional row index in [0, 18]
  int r = static_cast<int>(x);
  if (r >= kRows - 1) r = kRows - 2;
  const double w = x - r;
  return (1.0 - w) * table[r][col] + w * table[r + 1][col];
}

double interpolate(const double (&table)[kRows][3], int which, double s, double nu) {
  // Quadratic Lagrange interpolation of 1/C through nu = 0, 0.25, 0.5.
  const double l0 = (nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5));
  const double l1 = (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5));
  const double l2 = (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25));
  const double inv = l0 / column_value(table, which, s, 0) + l1 / column_value(table, which, s, 1) +
                     l2 / column_value(table, which, s, 2);
  return 1.0 / inv;
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_over_b, double poisson) {
  if (!(a_over_b > 0.0) || !std::isfinite(a_over_b) || !(poisson >= 0.0 && poisson <= 0.5)) {
    std::ostringstream msg;
    msg << "kalker_coefficients: need a/b > 0 and finite and Poisson's ratio in [0, 0.5], got a/b = "
        << a_over_b << ", nu = " << poisson;
    throw std::invalid_argument(msg.str());
  }
  // Unified table parameter: s = a/b on the a <= b side, s = 2 - b/a on the a > b side.
  const double s = a_over_b <= 1.0 ? a_over_b : 2.0 - 1.0 / a_over_b;
  KalkerCoefficients c;
  c.c11 = interpolate(kC11, 0, s, poisson);
  c.c22 = interpolate(kC22, 1, s, poisson);
  c.c23 = interpolate(kC23, 2, s, poisson);
  c.c33 = interpolate(kC33, 3, s, poisson);
  return c;
}

}  // namespace wrc
