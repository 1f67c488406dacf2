// SPDX-License-Identifier: Apache-2.0
#include "core/profile/circle_rail.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/profile/builtin_profiles.hpp"

namespace wrc {

CircleRailProfile::CircleRailProfile(double radius)
    : radius_(radius), half_width_(std::min(0.036, 0.9 * radius)) {
  if (!std::isfinite(radius) || radius <= 0.0) {
    throw std::invalid_argument("circle rail profile: radius must be positive and finite");
  }
}

ProfileSample CircleRailProfile::evaluate(double u) const {
  const double q = std::max(radius_ * radius_ - u * u, 1e-12 * radius_ * radius_);
  const double root = std::sqrt(q);
  // sqrt(R^2 - u^2) - R written without cancellation near the top.
  return {-u * u / (root + radius_), -u / root, -radius_ * radius_ / (q * root)};
}

double CircleRailProfile::lower() const { return -half_width_; }
double CircleRailProfile::upper() const { return half_width_; }
ProfileSide CircleRailProfile::side() const { return ProfileSide::kRail; }

std::string CircleRailProfile::name() const {
  std::ostringstream out;
  out.precision(17);
  out << kCirclePrefix << radius_;
  return out.str();
}

}  // namespace wrc
