// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The two limits a run's wheel forces are judged against (docs/run-quantities.md): Nadal's
/// flange-climb limit of one wheel's Y/Q and Prud'homme's track-shift limit of an axle's sum of Y.

namespace wrc {

/// The largest flange angle of the S1002 wheel profile (EN 13715): its flank is a straight line of
/// slope dF/ds = -2.747477419 = -tan(70 deg) [rad] (7 pi / 18; checked against the built-in S1002 in
/// tests/unit/dynamics_safety_limits_test.cpp). The default of the run parameter flange_angle.
inline constexpr double kS1002FlangeAngle = 1.2217304763960306;

/// The bound a flange angle must stay below: a vertical flange, pi / 2 [rad] (exclusive).
inline constexpr double kMaxFlangeAngle = 1.5707963267948966;

/// Nadal's limit of Y/Q for flange climbing: (tan delta - mu) / (1 + mu tan delta) [-], the ratio at
/// which a wheel in flange contact at the flange angle delta, sliding upwards with friction mu, is in
/// equilibrium (equal to tan(delta - atan mu)).
/// @param flange_angle delta [rad], in (0, pi/2).  @param friction mu [-], >= 0.
/// @throws std::invalid_argument naming the value when delta is outside (0, pi/2) or mu is negative
///         or either is not finite.
double nadal_limit(double flange_angle, double friction);

/// Prud'homme's limit of the track-shift force of one axle: 1e4 N + P / 3 [N] with P the axle load
/// [N] (the usual form 10 kN + P / 3 with P in kN; the factor alpha = 0.85 that acceptance codes put
/// in front of it for freight wagons is left to the reader, docs/run-quantities.md).
/// @param axle_load P [N], > 0.
/// @throws std::invalid_argument naming the value when P is not positive and finite.
double prudhomme_limit(double axle_load);

}  // namespace wrc
