// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// FASTSIM: Kalker's simplified theory of rolling contact (Kalker 1982, VSD 11:1-13) on an elliptic
/// Hertzian patch, with the parabolic traction bound and the CENTRE-VALUE discretisation.
///
/// Model: the surface displacement is proportional to the local traction, u = L p, with three
/// flexibilities chosen so that the small-creep limit reproduces Kalker's linear theory:
///   L1 = 8a / (3 C11 G),  L2 = 8a / (3 C22 G),  L3 = pi a^2 / (4 C23 G c),  c = sqrt(a b).
/// Traction bound: g(x, y) = mu (2N / (pi a b)) (1 - x^2/a^2 - y^2/b^2), whose integral is mu N.
///
/// Discretisation: m_y strips of width 2b/m_y centred at y_j; strip j has half-length
/// a_j = a sqrt(1 - y_j^2/b^2) and m_x elements of length 2a_j/m_x (every strip the same number of
/// elements, so the result is continuous in a and b). Material enters at the leading edge x = +a_j with
/// zero traction. At element i (centre x_i) the rigid-slip increment is
///   u = ((xi_x/L1 - phi_s y_j/L3) dx, (xi_y/L2 + phi_s x_i/L3) dx),
/// the element is charged with the half-step traction p_prev - u/2 and the value p_prev - u is carried
/// to the next element, both capped in magnitude by the bound at the element centre (an element whose
/// half-step value is capped counts as slipping). Forces on the wheel:
///   Fx = sum p_x dx dy,  Fy = sum p_y dx dy,  Mz = sum (x p_y - y p_x) dx dy.
/// Compared with the plain scheme (charging p_prev - u to the whole element) this removes the
/// first-order bias: the linear limit is reproduced to +0.5 % at 10x10 and +0.13 % at 20x20 (midpoint
/// rule over the strips, 1/(2 m_y^2)), and within 0.3 % of the strip-analytic partial-slip solution.
/// Known limits of the scheme (measured in tests/unit/contact_fastsim_test.cpp):
///  - at the onset of slip a slip zone shorter than half an element is not resolved (no element is
///    capped), so the result stays on the linear value: error up to ~1/(2 m_x) (1.7 % measured at 20x20
///    for xi_x = 1e-4 on the 80 kN example patch);
///  - with large spin (phi_s a well above the creepages, flange contact) convergence in m_x is only first
///    order and the strip count hardly matters: 20x20 is 3.2 % off in Fy for phi_s = 2 1/m, 80x20 1.1 %,
///    160x20 0.6 %. Use m_x >= 80..160 for flange contact when the lateral force matters to ~1 %.
///
/// Cost: m_x m_y element updates, no iteration, no allocation per call.

#include <vector>

#include "core/contact/creep_forces.hpp"
#include "core/contact/kalker_coefficients.hpp"

namespace wrc {

/// The FASTSIM grid used unless another is asked for: elements per strip and strips [-].
inline constexpr int kDefaultFastsimGrid = 20;
/// The element counts per direction a Fastsim takes [-], both included.
inline constexpr int kMinFastsimCount = 1;
inline constexpr int kMaxFastsimCount = 10000;

/// A FASTSIM solver for one grid size. Construction precomputes the normalised grid; solve() is
/// const, allocation-free and thread-safe.
class Fastsim {
 public:
  /// @param elements_per_strip m_x, elements along the rolling direction in every strip [-],
  /// kMinFastsimCount..kMaxFastsimCount (1..10000).
  /// @param strips m_y, number of strips across the lateral direction [-], the same range.
  /// @throws std::invalid_argument naming the values when a count is outside that range.
  explicit Fastsim(int elements_per_strip = kDefaultFastsimGrid, int strips = kDefaultFastsimGrid);

  /// Creep forces with precomputed Kalker coefficients (C11, C22, C23 are used; C33 is not).
  /// @param patch a, b [m], N [N], G [Pa], mu [-] (nu is only used by the other overload).
  /// @param coefficients Kalker's coefficients for a/b and nu of the patch [-].
  /// @param creepages xi_x, xi_y [-], phi_s [1/m].
  /// @return Fx, Fy [N] and Mz [N m] on the wheel, and the slipping area fraction [-].
  /// @throws std::invalid_argument for an invalid patch, non-positive C11/C22/C23 or non-finite creepages.
  CreepForces solve(const CreepPatch& patch, const KalkerCoefficients& coefficients,
                    const Creepages& creepages) const;

  /// Creep forces; Kalker's coefficients from a/b and the patch's Poisson's ratio.
  CreepForces solve(const CreepPatch& patch, const Creepages& creepages) const;

  /// m_x, elements per strip along the rolling direction [-].
  int elements_per_strip() const { return m_x_; }
  /// m_y, number of strips [-].
  int strips() const { return m_y_; }

 private:
  int m_x_;
  int m_y_;
  std::vector<double> strip_eta_;         // y_j / b at strip centres
  std::vector<double> strip_half_length_; // a_j / a = sqrt(1 - eta_j^2)
  std::vector<double> element_zeta_;      // x_i / a_j at element centres, leading edge first
  std::vector<double> element_bound_;     // 1 - zeta_i^2
};

/// One-off convenience: Fastsim(elements_per_strip, strips).solve(patch, creepages). Allocates the grid;
/// build a Fastsim once for repeated calls.
CreepForces fastsim(const CreepPatch& patch, const Creepages& creepages,
                    int elements_per_strip = kDefaultFastsimGrid, int strips = kDefaultFastsimGrid);

}  // namespace wrc
