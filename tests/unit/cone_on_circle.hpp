// SPDX-License-Identifier: Apache-2.0
#pragma once
// Test support: the linear geometry the vehicle tests compare with theory, a cone of the given
// conicity on a 0.1 m circular rail head, gauge 1.5 m measured at rail level, no inclination, the
// wheel's nominal radius r0. Near the centre its rolling-radius difference is 2 conicity y to 4
// digits over 2 mm (geometry_cone_circle_test.cpp).
#include <memory>
#include <string>

#include "core/geometry/wheelset_geometry.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc::test {

/// conicity: the profile factory's "conic:<conicity>" [-]; nominal_radius r0 [m].
inline std::shared_ptr<const WheelsetGeometry> cone_on_circle(const std::string& conicity, double nominal_radius) {
  TrackParameters t;
  t.gauge = 1.5;
  t.gauge_depth = 0.0;
  t.inclination = 0.0;
  t.nominal_radius = nominal_radius;
  return std::make_shared<const WheelsetGeometry>(make_profile("conic:" + conicity, ProfileSide::kWheel),
                                                  make_profile("circle:0.1", ProfileSide::kRail), t);
}

}  // namespace wrc::test
