// SPDX-License-Identifier: Apache-2.0
#include "core/profile/conic.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/profile/builtin_profiles.hpp"

namespace wrc {
namespace {
constexpr double kHalfWidth = 0.06;
}  // namespace

ConicProfile::ConicProfile(double slope) : slope_(slope) {
  if (!std::isfinite(slope)) {
    throw std::invalid_argument("conic profile: slope must be finite");
  }
}

ProfileSample ConicProfile::evaluate(double s) const { return {-slope_ * s, -slope_, 0.0}; }

double ConicProfile::lower() const { return -kHalfWidth; }
double ConicProfile::upper() const { return kHalfWidth; }
ProfileSide ConicProfile::side() const { return ProfileSide::kWheel; }

std::string ConicProfile::name() const {
  std::ostringstream out;
  out.precision(17);
  out << kConicPrefix << slope_;
  return out.str();
}

}  // namespace wrc
