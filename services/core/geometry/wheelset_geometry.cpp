// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/wheelset_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wrc {
namespace {
// Sampling of the distance that gives the common-point search its level [m].
constexpr double kCoarseStep = 5.0e-3;
}  // namespace

ProfilePtr WheelsetGeometry::checked_wheel(ProfilePtr wheel) {
  if (!wheel) throw std::invalid_argument("no wheel profile");
  if (wheel->side() != ProfileSide::kWheel)
    throw std::invalid_argument("profile '" + wheel->name() + "' is a rail profile, a wheel profile is needed");
  return wheel;
}

WheelsetGeometry::WheelsetGeometry(ProfilePtr wheel, ProfilePtr rail, const TrackParameters& track)
    : wheel_(checked_wheel(std::move(wheel))), track_(track),
      left_rail_(rail, track, WheelSide::kLeft), right_rail_(rail, track, WheelSide::kRight),
      wheel_envelope_(wheel_->lower(), wheel_->upper(), 1e-3, 32, 1.25, [this](double s, double& d1, double& d2) {
        const ProfileSample f = wheel_->evaluate(s);
        d1 = f.slope;
        d2 = f.second_derivative;
      }) {
  // Flange apex: the highest point of the profile on the flange side (s <= 0).
  const double lo = wheel_->lower(), hi = std::min(0.0, wheel_->upper());
  double best = -1e300;
  for (int i = 0; i <= 20000; ++i) {
    const double s = lo + (hi - lo) * i / 20000.0;
    const double f = wheel_->evaluate(s).height;
    if (f > best) {
      best = f;
      flange_apex_ = s;
    }
  }
}

ContactLocus WheelsetGeometry::locus(WheelSide side, const WheelsetPose& pose) const {
  return ContactLocus(*wheel_, rail(side), track_, side, pose, &wheel_envelope_);
}

std::vector<ContactPoint> WheelsetGeometry::potential_points(WheelSide side, const WheelsetPose& pose,
                                                             const PotentialPointSearch& search) const {
  return find_potential_points(locus(side, pose), search);
}

std::optional<ContactPoint> WheelsetGeometry::common_point(WheelSide side, const WheelsetPose& pose,
                                                           const PotentialPointSearch& search) const {
  // Only the minima at or below the lowest distance of a coarse sampling can be the common point:
  // look for those alone (find_minima_below certifies that nothing else lies lower).
  const ContactLocus c = locus(side, pose);
  double lowest = std::numeric_limits<double>::infinity();
  for (double s = c.s_lower(); s <= c.s_upper(); s += kCoarseStep) {
    double d, g;
    c.distance_and_slope(s, d, g);
    if (d < lowest) lowest = d;
  }
  if (!std::isfinite(lowest)) return std::nullopt;
  return select_common_point(find_minima_below(c, lowest + 1e-12, search));
}

}  // namespace wrc
