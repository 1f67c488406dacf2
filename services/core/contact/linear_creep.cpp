// SPDX-License-Identifier: Apache-2.0
#include "core/contact/linear_creep.hpp"

#include <cmath>

namespace wrc {

CreepForces linear_creep_forces(const CreepPatch& patch, const KalkerCoefficients& k, const Creepages& cr) {
  validate_creep_patch(patch, "linear_creep_forces");
  validate_creepages(cr, "linear_creep_forces");
  const double c = std::sqrt(patch.a * patch.b);
  const double g_c2 = patch.shear_modulus * c * c;
  CreepForces f;
  f.fx = -g_c2 * k.c11 * cr.longitudinal;
  f.fy = -g_c2 * k.c22 * cr.lateral - g_c2 * c * k.c23 * cr.spin;
  f.mz = g_c2 * c * k.c23 * cr.lateral - g_c2 * c * c * k.c33 * cr.spin;
  f.slip_fraction = 0.0;
  return f;
}

CreepForces linear_creep_forces(const CreepPatch& patch, const Creepages& creepages) {
  validate_creep_patch(patch, "linear_creep_forces");
  return linear_creep_forces(patch, kalker_coefficients(patch.a / patch.b, patch.poisson), creepages);
}

}  // namespace wrc
