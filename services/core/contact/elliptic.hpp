// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Complete elliptic integrals of the first and second kind, K and E, by the arithmetic-geometric
/// mean (AGM). Used by the Hertz solution (hertz.hpp).
///
/// Notation: modulus k = e (the eccentricity of a Hertz ellipse, e^2 = 1 - (b/a)^2 for a >= b) and
/// complementary modulus k' = sqrt(1 - k^2) (= b/a, the ratio of the minor to the major semi-axis).
///   K(k) = int_0^{pi/2} dt / sqrt(1 - k^2 sin^2 t),   E(k) = int_0^{pi/2} sqrt(1 - k^2 sin^2 t) dt.
/// Besides K and E the result carries the two differences K - E and E - k'^2 K, computed without
/// cancellation. Both vanish like k^2 as k -> 0, where forming them from K and E would lose all digits;
/// the Hertz axis-ratio equation needs exactly these differences.

namespace wrc {

/// K, E and the two cancellation-free differences for one modulus. All dimensionless.
struct CompleteEllipticIntegrals {
  double K = 0;             ///< complete elliptic integral of the first kind K(k) [-]
  double E = 0;             ///< complete elliptic integral of the second kind E(k) [-]
  double K_minus_E = 0;     ///< K - E [-], accurate also for small k (~ pi k^2 / 4)
  double E_minus_kc2_K = 0; ///< E - k'^2 K [-], accurate also for small k (~ pi k^2 / 4)
};

/// K and E from the complementary modulus k' = sqrt(1 - k^2) [-], 0 < k' <= 1.
/// This is the well-conditioned entry point when k is close to 1 (very elongated ellipses): pass the
/// axis ratio b/a directly instead of forming sqrt(1 - e^2). Relative accuracy ~1e-15.
/// @throws std::invalid_argument if k' is not in (0, 1] or is NaN.
CompleteEllipticIntegrals complete_elliptic_integrals_from_complement(double k_complement);

/// K and E from the modulus k = e [-], 0 <= k < 1 (k' is formed as sqrt((1 - k)(1 + k))).
/// @throws std::invalid_argument if k is not in [0, 1) or is NaN.
CompleteEllipticIntegrals complete_elliptic_integrals(double k);

}  // namespace wrc
