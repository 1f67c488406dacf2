// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Where an elastic contact loads two points at once: the rule that the spline fit and the
/// interpolation table share for the width of a common-point jump's transition.
///
/// A jump of the rigid contact point is where two local minima of one wheel's distance are equally
/// low. Pressed down by its Hertz approach against the rail, an elastic wheel touches at every
/// minimum less than the approach above the lowest, so both points carry load while the two
/// touching heights differ by less than the approach at the nominal load: the transition is a width
/// in that height difference, not in y (docs/spline-model.md, "Where both points carry load").

namespace wrc {

/// Default normal load per wheel whose Hertz approach sets a transition's half-width [N]: the
/// paper's benchmark load Fz / 2 = 154715 N / 2.
inline constexpr double kDefaultTransitionLoad = 77357.5;
/// Default cap on a transition's half-width in height [m]: above any approach of steel wheels on
/// steel rails, so the approach decides.
inline constexpr double kDefaultTransition = 1e-3;
/// Validated ranges: the cap in [0, kMaxTransition] [m] (0: no physical transition), the load in
/// [kMinTransitionLoad, kMaxTransitionLoad] [N].
inline constexpr double kMaxTransition = 2e-3;
inline constexpr double kMinTransitionLoad = 1.0;
inline constexpr double kMaxTransitionLoad = 1e6;

/// The Hertz approach [m] of a contact of relative curvatures A (rolling) and B (lateral) [1/m]
/// (contact_shape()) under normal_load [N], with the default material (ContactMaterial): the
/// height within which a second local minimum above the lowest carries load too.
double sharing_approach(double A, double B, double normal_load);

/// The C2 smooth maximum of two touching heights z_a and z_b within their transition of
/// half-width h > 0 [m]: with d = z_b - z_a and u = (1 + d / h) / 2 clamped to [0, 1],
/// z = z_a + h phi(d / h), phi(t) = 2 (u^6 - 3 u^5 + 5/2 u^4), so that phi' = w(u) =
/// u^3 (10 - 15 u + 6 u^2) (the quintic smoothstep) and phi'' = w'(u) / 2; the higher height
/// outside |d| < h, z >= max(z_a, z_b) everywhere (docs/spline-model.md, "The smooth maximum").
struct SmoothMaximum {
  double value = 0;        ///< z [m]
  double share = 0;        ///< w = dz / dz_b, the upper point's share, 1 - w = dz / dz_a [-]
  double share_slope = 0;  ///< dw / dd = w'(u) / (2 h) [1/m]
};
SmoothMaximum smooth_maximum(double z_a, double z_b, double h);

}  // namespace wrc
