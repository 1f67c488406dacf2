// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/safety_limits.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

constexpr double kPrudhommeConstant = 1.0e4;             // [N] the 10 kN of 10 kN + P / 3

}  // namespace

double nadal_limit(double flange_angle, double friction) {
  if (!(flange_angle > 0.0 && flange_angle < kMaxFlangeAngle)) {
    std::ostringstream msg;
    msg << "flange_angle = " << flange_angle << " rad is outside (0, pi/2): Nadal's limit needs a flange angle "
        << "between the tread (0) and a vertical flange (pi/2)";
    throw std::invalid_argument(msg.str());
  }
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    std::ostringstream msg;
    msg << "friction = " << friction << " is invalid: Nadal's limit needs a friction coefficient >= 0";
    throw std::invalid_argument(msg.str());
  }
  const double t = std::tan(flange_angle);
  return (t - friction) / (1.0 + friction * t);
}

double prudhomme_limit(double axle_load) {
  if (!(axle_load > 0.0) || !std::isfinite(axle_load)) {
    std::ostringstream msg;
    msg << "axle load P = " << axle_load << " N is invalid: Prud'homme's limit needs P > 0";
    throw std::invalid_argument(msg.str());
  }
  return kPrudhommeConstant + axle_load / 3.0;
}

}  // namespace wrc
