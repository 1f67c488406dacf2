// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Kalker's linear theory of rolling contact (no saturation): valid for small creepages, where the
/// whole patch adheres. Forces on the wheel, c = sqrt(a b):
///   Fx = -G c^2 C11 xi_x
///   Fy = -G c^2 C22 xi_y - G c^3 C23 phi_s
///   Mz = +G c^3 C23 xi_y - G c^4 C33 phi_s     (C33 of lower confidence, see kalker_coefficients.hpp)

#include "core/contact/creep_forces.hpp"
#include "core/contact/kalker_coefficients.hpp"

namespace wrc {

/// Linear-theory creep forces with precomputed coefficients (normal force and friction unused).
/// @param patch a, b [m], G [Pa] (validated).  @param coefficients Kalker's C11..C33 [-].
/// @param creepages xi_x, xi_y [-], phi_s [1/m].
/// @return Fx, Fy [N], Mz [N m] on the wheel; slip_fraction = 0.
/// @throws std::invalid_argument for an invalid patch or non-finite creepages.
CreepForces linear_creep_forces(const CreepPatch& patch, const KalkerCoefficients& coefficients,
                                const Creepages& creepages);

/// Linear-theory creep forces; Kalker's coefficients from a/b and the patch's Poisson's ratio.
CreepForces linear_creep_forces(const CreepPatch& patch, const Creepages& creepages);

}  // namespace wrc
