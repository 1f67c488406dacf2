// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The S1002 wheel profile (UIC 510-2 / EN 13715, flange thickness 32.5 mm) from its analytic
/// piecewise definition (the "Netter/DLR" coefficient form, sections A to H).

#include <string>
#include <vector>

#include "core/profile/profile.hpp"

namespace wrc {

/// S1002 wheel profile, analytic. Lateral coordinate s [m] from the taping line, positive towards
/// the field side; domain [-0.070, 0.060] m (flange back to outer tread).
///
/// Each of the eight sections is evaluated only inside its own range, and the square-root arguments
/// of the arc sections are clamped at a tiny positive value, so no NaN can appear.
///
/// Continuity: the published coefficients are not exactly C0 at two breakpoints: the height jumps
/// by about 1.2e-7 m (0.118 um) at s = -0.035 m (sections C/D) and by about 3.7e-8 m at
/// s = -0.026 m (sections B/C); the slope jumps by up to about 2e-4 there. The other breakpoints
/// are continuous to about 1e-10 m. The second derivative jumps at every breakpoint (arcs meet
/// lines and polynomials), as for any profile built from arcs: breakpoints() lists them. At
/// s = -0.070 m the flange-back arc becomes vertical; the clamp keeps the slope finite there.
class S1002Profile final : public Profile {
 public:
  /// Height F(s) [m], slope dF/ds [-] and second derivative d2F/ds2 [1/m].
  ProfileSample evaluate(double s) const override;
  /// Flange back, s = -0.070 [m].
  double lower() const override;
  /// Outer end of the tread, s = +0.060 [m].
  double upper() const override;
  /// The seven interior section boundaries [m], increasing.
  std::vector<double> breakpoints() const override;
  /// Always ProfileSide::kWheel.
  ProfileSide side() const override;
  /// "S1002 (analytic)".
  std::string name() const override;
};

/// Height F(S), slope and second derivative of S1002 in the published units: S and F in [mm],
/// second derivative in [1/mm]. Exposed for tests and for the metre-based class above.
ProfileSample s1002_evaluate_mm(double s_mm);

}  // namespace wrc
