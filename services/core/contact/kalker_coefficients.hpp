// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Kalker's creepage coefficients C11, C22, C23, C33 of the linear theory of rolling contact, for an
/// elliptic contact of semi-axes a (rolling) and b (lateral) between bodies of identical material.
///
/// Source: Kalker 1990, Table E.3 (values also in the public CONTACT code); the table, its known
/// printing error and the reference values at nu = 0.28 are described in docs/contact-mechanics.md,
/// "Kalker's linear theory and coefficients". C11, C22, C23 are cross-checked against CONTACT; C33 is
/// of LOWER CONFIDENCE (no second source; FASTSIM does not use it, only the linear theory's spin
/// moment does).
///
/// Interpolation (CONTACT's approach):
///  - the table parameter is g = a/b for a <= b and g = b/a for a > b; linear in g between rows;
///  - in Poisson's ratio, quadratic Lagrange interpolation of 1/C through nu = 0, 0.25, 0.5;
///  - a < b side below g = 0.1 (very wide ellipses): Kalker's asymptotes
///      C11 = pi^2 / (4 (1 - nu)),  C22 = pi^2 / 4,  C23 = pi sqrt(g) / (3 (1 - nu)) (1 + nu (ln(16/g) - 5)),
///    joined continuously to the g = 0.1 row: C11 and C22 linearly between their g -> 0 limits and the row,
///    C23 (and C33) as the row value times asymptote(g) / asymptote(0.1);
///  - a > b side below g = b/a = 0.1 (very long ellipses): power-law extrapolation of the last table
///    interval, C(g) = C(0.1) (g / 0.1)^p with p from the rows b/a = 0.2 and 0.1 (log-log linear, continuous,
///    follows the steep growth of the table; lower confidence than the table itself).

namespace wrc {

/// Kalker's linear-theory coefficients. All dimensionless.
struct KalkerCoefficients {
  double c11 = 0;  ///< longitudinal creepage coefficient C11 [-]
  double c22 = 0;  ///< lateral creepage coefficient C22 [-]
  double c23 = 0;  ///< lateral-spin coupling coefficient C23 = C32 [-]
  double c33 = 0;  ///< spin coefficient C33 [-] (LOWER CONFIDENCE: unverified table)
};

/// Kalker's coefficients for the axis ratio a/b and Poisson's ratio nu.
/// @param a_over_b ratio of the rolling to the lateral semi-axis [-], > 0 (tested for 1e-3 .. 1e3).
/// @param poisson Poisson's ratio nu [-], in [0, 0.5].
/// @throws std::invalid_argument naming the values when a_over_b <= 0, nu outside [0, 0.5], or NaN.
KalkerCoefficients kalker_coefficients(double a_over_b, double poisson);

}  // namespace wrc
