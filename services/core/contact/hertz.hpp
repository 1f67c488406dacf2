// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Hertz theory for two elastic bodies of identical material touching at one point: the contact
/// ellipse, the maximum pressure, the penetration and the force-penetration law N = C_H delta^{3/2},
/// from the two principal relative curvatures, by the complete elliptic integrals (no fitted tables).
///
/// Conventions: x is the rolling direction and y the lateral direction in the contact plane; the
/// undeformed gap is h = A x^2 + B y^2. a is the semi-axis along x, b along y. The larger semi-axis lies
/// along the direction of the smaller curvature: B > A (the normal tread case) gives a > b.
/// Material: E* = E / (2 (1 - nu^2)) = G / (1 - nu) (see contact_modulus()).

namespace wrc {

/// The contact modulus E* [Pa] of two bodies of identical material, E* = G / (1 - nu) = E / (2 (1 - nu^2)).
/// @param shear_modulus G [Pa], > 0.  @param poisson nu [-], in [0, 0.5).
/// @throws std::invalid_argument naming the values when G <= 0, nu outside [0, 0.5) or NaN.
double contact_modulus(double shear_modulus, double poisson);

/// The shape of the Hertz ellipse, which depends on the curvatures only (not on the load).
struct HertzShape {
  double A = 0;              ///< relative curvature in the rolling direction [1/m]
  double B = 0;              ///< relative curvature in the lateral direction [1/m]
  double axis_ratio = 1;     ///< a / b, rolling over lateral semi-axis [-]
  double minor_over_major = 1; ///< k' = min(a, b) / max(a, b) [-], in (0, 1]
  double eccentricity = 0;   ///< e = sqrt(1 - k'^2) [-]
  double K = 0;              ///< complete elliptic integral of the first kind K(e) [-]
  double E = 0;              ///< complete elliptic integral of the second kind E(e) [-]
  double m = 1;              ///< Hertz coefficient of a: a = m [3N / (4 E* (A+B))]^{1/3} [-]
  double n = 1;              ///< Hertz coefficient of b: b = n [3N / (4 E* (A+B))]^{1/3} [-]
};

/// One loaded Hertz contact.
struct HertzContact {
  HertzShape shape;          ///< ellipse shape (curvatures, eccentricity, m, n)
  double a = 0;              ///< semi-axis in the rolling direction [m]
  double b = 0;              ///< semi-axis in the lateral direction [m]
  double max_pressure = 0;   ///< p0 = 3 N / (2 pi a b) [Pa]
  double penetration = 0;    ///< approach of the two bodies delta [m]
  double normal_force = 0;   ///< N [N]
  double stiffness = 0;      ///< C_H in N = C_H delta^{3/2} [N/m^{3/2}]
};

/// Solves the Hertz axis-ratio equation max(A,B)/min(A,B) = (E - k'^2 K) / (k'^2 (K - E)) for the
/// ellipse shape. The unknown is t = ln k', in which the equation is almost linear; it is solved by a
/// safeguarded secant (Illinois) iteration to ~1e-14 in t. Valid for curvature ratios up to ~1e9
/// (a/b from about 1e-6 to 1e6), which includes a/b from 1/50 to 50 with wide margin.
/// @param A relative curvature in the rolling direction [1/m], > 0.
/// @param B relative curvature in the lateral direction [1/m], > 0.
/// @throws std::invalid_argument naming the values when A <= 0, B <= 0, NaN, or B/A beyond the range.
HertzShape hertz_shape(double A, double B);

/// The Hertz stiffness C_H [N/m^{3/2}] of N = C_H delta^{3/2}:
/// C_H = (2 pi E* / 3) sqrt(E(e)) / (sqrt(A + B) K(e)^{3/2} k'), k' = min(a,b)/max(a,b).
/// @param shape from hertz_shape().  @param contact_modulus E* [Pa], > 0.
double hertz_stiffness(const HertzShape& shape, double contact_modulus);

/// Hertz contact for a given normal force: a, b, p0, delta and C_H.
/// @param shape from hertz_shape().  @param contact_modulus E* [Pa], > 0.  @param normal_force N [N], >= 0.
/// @throws std::invalid_argument naming the values when N < 0, E* <= 0 or NaN.
HertzContact hertz_from_force(const HertzShape& shape, double contact_modulus, double normal_force);

/// Hertz contact for a given penetration (elastic contact models): N = C_H delta^{3/2}, then the
/// semi-axes from the penetration directly: min(a,b) = sqrt(delta E / ((A + B) K)).
/// @param shape from hertz_shape().  @param contact_modulus E* [Pa], > 0.  @param penetration delta [m], >= 0.
/// @throws std::invalid_argument naming the values when delta < 0, E* <= 0 or NaN.
HertzContact hertz_from_penetration(const HertzShape& shape, double contact_modulus, double penetration);

/// The maximum pressure at the centre of a Hertz ellipse, p0 = 3 N / (2 pi a b) [Pa] (the
/// ellipsoidal pressure distribution p0 sqrt(1 - x^2/a^2 - y^2/b^2) integrated over the ellipse is
/// N); 0 when N = 0. The one place of this rule (HertzContact::max_pressure and the run's p_max).
/// @param normal_force N [N], >= 0.  @param a, b semi-axes [m], > 0 when N > 0.
/// @throws std::invalid_argument naming the values when N < 0 or not finite, or N > 0 with a or b
///         not positive and finite.
double hertz_max_pressure(double normal_force, double a, double b);

/// Convenience: hertz_from_force(hertz_shape(A, B), contact_modulus, normal_force).
/// @param A [1/m] > 0.  @param B [1/m] > 0.  @param contact_modulus E* [Pa].  @param normal_force N [N] >= 0.
HertzContact hertz_from_force(double A, double B, double contact_modulus, double normal_force);

}  // namespace wrc
