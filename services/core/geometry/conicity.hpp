// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Equivalent conicity by harmonic linearisation of the rolling-radius difference (EN 15302 style).

#include "core/geometry/rigid_wheelset.hpp"

namespace wrc {

/// Equivalent conicity [-] at lateral amplitude A [m]: the first Fourier coefficient of the
/// rolling-radius difference along the sinusoidal motion y = A sin(t), divided by 2A:
///   lambda_e = 1/(2 pi A) * integral_0^{2 pi} delta_r(A sin t) sin t dt,
/// evaluated with the midpoint rule on `samples` points (exact for trigonometric polynomials of
/// degree < samples; delta_r may jump, which the dense sampling resolves). A cone of slope lambda
/// on a knife-edge rail gives lambda a / (a - lambda r0) (a: taping half distance; the roll of the
/// rigid wheelset moves each contact r0 roll along the tread; lambda when that is neglected; tested
/// in geometry_cone_circle_test.cpp). This is the harmonic-linearisation method; EN 15302's
/// reference method (integral of the linearised wheelset equation) gives close but not identical
/// values for strongly non-linear delta_r. yaw [rad] is held fixed (0 in EN 15302).
/// Throws std::invalid_argument for A <= 0, A > 0.02 m, samples < 8, or NaN.
double equivalent_conicity(const RigidWheelsetSolver& solver, double amplitude, int samples = 512, double yaw = 0.0);

}  // namespace wrc
