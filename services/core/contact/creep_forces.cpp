// SPDX-License-Identifier: Apache-2.0
#include "core/contact/creep_forces.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

void require(bool ok, const char* where, const char* name, double value, const char* rule) {
  if (ok) return;
  std::ostringstream msg;
  msg << where << ": " << name << " = " << value << " " << rule;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void validate_creep_patch(const CreepPatch& p, const char* where) {
  require(p.a > 0.0 && std::isfinite(p.a), where, "semi-axis a", p.a, "m must be positive and finite");
  require(p.b > 0.0 && std::isfinite(p.b), where, "semi-axis b", p.b, "m must be positive and finite");
  require(p.normal_force >= 0.0 && std::isfinite(p.normal_force), where, "normal force N", p.normal_force,
          "N must be non-negative and finite");
  require(p.shear_modulus > 0.0 && std::isfinite(p.shear_modulus), where, "shear modulus G", p.shear_modulus,
          "Pa must be positive and finite");
  require(p.poisson >= 0.0 && p.poisson <= 0.5, where, "Poisson's ratio nu", p.poisson, "must be in [0, 0.5]");
  require(p.friction >= 0.0 && std::isfinite(p.friction), where, "friction coefficient mu", p.friction,
          "must be non-negative and finite");
}

void validate_creepages(const Creepages& c, const char* where) {
  require(std::isfinite(c.longitudinal), where, "longitudinal creepage xi_x", c.longitudinal, "must be finite");
  require(std::isfinite(c.lateral), where, "lateral creepage xi_y", c.lateral, "must be finite");
  require(std::isfinite(c.spin), where, "spin creepage phi_s", c.spin, "1/m must be finite");
}

}  // namespace wrc
