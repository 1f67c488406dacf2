// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/jump_transition.hpp"

#include <algorithm>

#include "core/contact/hertz.hpp"
#include "core/model_interface/contact_model.hpp"

namespace wrc {

double sharing_approach(double A, double B, double normal_load) {
  const ContactMaterial material;
  return hertz_from_force(A, B, contact_modulus(material.shear_modulus, material.poisson_ratio), normal_load)
      .penetration;
}

SmoothMaximum smooth_maximum(double z_a, double z_b, double h) {
  const double u = std::clamp(0.5 * (1.0 + (z_b - z_a) / h), 0.0, 1.0);
  SmoothMaximum m;
  m.share = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
  m.share_slope = 15.0 * u * u * (1.0 - u) * (1.0 - u) / h;
  m.value = u >= 1.0 ? z_b : z_a + h * 2.0 * u * u * u * u * (2.5 + u * (-3.0 + u));
  return m;
}

}  // namespace wrc
