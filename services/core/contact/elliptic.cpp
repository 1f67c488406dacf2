// SPDX-License-Identifier: Apache-2.0
#include "core/contact/elliptic.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {

namespace {

// AGM with both moduli given: k' and k^2 = 1 - k'^2, each passed in its most accurate form.
CompleteEllipticIntegrals agm(double k_complement, double k2) {
  // AGM of (1, k'): a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n)/2, c_0 = k.
  // K = pi / (2 a_inf), K - E = K * sum_{n>=0} 2^{n-1} c_n^2 (Abramowitz & Stegun 17.6.3-4).
  double a = 1.0;
  double b = k_complement;
  double sum = 0.5 * k2;  // 2^{-1} c_0^2
  double weight = 0.5;
  for (int n = 0; n < 40; ++n) {
    const double c = 0.5 * (a - b);
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
    if (std::abs(c) <= 1e-17 * a) break;  // quadratic convergence: about 5 steps for k' >= 1e-3
  }
  CompleteEllipticIntegrals r;
  r.K = 3.14159265358979323846 / (2.0 * a);
  r.K_minus_E = r.K * sum;
  r.E = r.K - r.K_minus_E;
  // E - k'^2 K = k^2 K - (K - E) = K (k^2 - sum); the terms of sum beyond n = 0 are O(k^4).
  r.E_minus_kc2_K = r.K * (0.5 * k2 - (sum - 0.5 * k2));
  return r;
}

}  // namespace

CompleteEllipticIntegrals complete_elliptic_integrals_from_complement(double k_complement) {
  if (!(k_complement > 0.0 && k_complement <= 1.0)) {
    std::ostringstream msg;
    msg << "complete_elliptic_integrals: complementary modulus k' = " << k_complement << " is not in (0, 1]";
    throw std::invalid_argument(msg.str());
  }
  // k^2 = (1 - k')(1 + k') as a product keeps full relative accuracy for k' near 1.
  return agm(k_complement, (1.0 - k_complement) * (1.0 + k_complement));
}

CompleteEllipticIntegrals complete_elliptic_integrals(double k) {
  if (!(k >= 0.0 && k < 1.0)) {
    std::ostringstream msg;
    msg << "complete_elliptic_integrals: modulus k = " << k << " is not in [0, 1)";
    throw std::invalid_argument(msg.str());
  }
  return agm(std::sqrt((1.0 - k) * (1.0 + k)), k * k);
}

}  // namespace wrc
