// SPDX-License-Identifier: Apache-2.0
// Placement of the rails in the track frame: gauge point, top of rail, inclination, and the rail
// surface graph z(y) with its derivatives.

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/placed_rail.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

ProfilePtr uic60() { return make_profile("UIC60", ProfileSide::kRail); }

// EN 60E1 at 1:40 and gauge 1435 mm: docs/profiles.md ("Placement") derives the rail axis at
// |y| = 753.035 mm and the top of rail at |y| = 760.53 mm (7.496 mm outward of the axis). Tolerance
// 1 um: the reference numbers are given to 1 um.
TEST(GeometryPlacement, Uic60AtOneInFortyMatchesReferencePlacement) {
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const double sigma = side_sign(side);
    PlacedRail rail(uic60(), TrackParameters{}, side);
    EXPECT_NEAR(rail.axis_y(), sigma * 0.753035, 1e-6);
    double y_top, z_top;
    rail.profile_to_track(rail.u_top(), y_top, z_top);
    EXPECT_NEAR(y_top, sigma * 0.76053, 1e-5);
    EXPECT_NEAR(z_top, 0.0, 1e-15);
    EXPECT_NEAR(rail.u_top(), 0.300 * std::sin(std::atan(1.0 / 40)), 1e-6);
    EXPECT_DOUBLE_EQ(rail.gauge_point_y(), sigma * 0.7175);
  }
}

// The gauge face 14 mm below the top of rail lies at |y| = gauge/2 (to 1e-9 m), and no rail point
// within that band is further inside; the top of rail is the highest point.
TEST(GeometryPlacement, GaugePointIsInnermostPointWithinGaugeDepth) {
  for (const char* incl : {"1:40", "1:20", "none"}) {
    TrackParameters track;
    track.inclination = parse_inclination(incl);
    PlacedRail rail(uic60(), track, WheelSide::kLeft);
    const Profile& p = rail.profile();
    double highest = -1e9;
    for (int i = 0; i <= 20000; ++i) {
      const double u = p.lower() + (p.upper() - p.lower()) * i / 20000.0;
      double y, z;
      rail.profile_to_track(u, y, z);
      highest = std::max(highest, z);
      if (z >= -track.gauge_depth) {
        EXPECT_GE(y, 0.7175 - 1e-12) << incl << " u=" << u;
      }
    }
    EXPECT_LE(highest, 1e-12) << incl;
    EXPECT_GT(highest, -1e-8) << incl;
    // Bisection for the gauge-side point exactly gauge_depth below the top: it is the gauge point.
    double lo = p.lower(), hi = rail.u_top();
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      double y, z;
      rail.profile_to_track(mid, y, z);
      (z < -track.gauge_depth ? lo : hi) = mid;
    }
    double y, z;
    rail.profile_to_track(hi, y, z);
    EXPECT_NEAR(y, 0.7175, 1e-9) << incl;
  }
}

// z(y), dz/dy and d2z/dy2 of the placed rail against central differences (h = 1e-6 m: truncation
// error ~h^2 * z''' < 1e-8, rounding ~1e-16/h^2 = 1e-4 for the second derivative, hence 1e-3 relative).
TEST(GeometryPlacement, RailSurfaceDerivativesMatchFiniteDifferences) {
  PlacedRail rail(uic60(), TrackParameters{}, WheelSide::kRight);
  const double h = 1e-6;
  for (double y = rail.y_lower() + 0.002; y < rail.y_upper() - 0.002; y += 0.0011) {
    const RailSample r = rail.at(y), rp = rail.at(y + h), rm = rail.at(y - h);
    ASSERT_TRUE(r.valid && rp.valid && rm.valid);
    EXPECT_NEAR(r.slope, (rp.z - rm.z) / (2 * h), 1e-6 * (1 + std::fabs(r.slope))) << y;
    EXPECT_NEAR(r.d2, (rp.slope - rm.slope) / (2 * h), 1e-3 * (1 + std::fabs(r.d2))) << y;
    // The surface point maps back onto itself through the profile coordinate.
    double yy, zz;
    rail.profile_to_track(r.u, yy, zz);
    EXPECT_NEAR(yy, y, 1e-12);
    EXPECT_NEAR(zz, r.z, 1e-12);
  }
  EXPECT_FALSE(rail.at(rail.y_upper() + 0.001).valid);
  EXPECT_FALSE(rail.at(rail.y_lower() - 0.001).valid);
}

// A wheel profile cannot be placed as a rail, and bad track values are rejected by name.
TEST(GeometryPlacement, RejectsWheelAsRailAndBadTrack) {
  EXPECT_THROW(PlacedRail(make_profile("S1002", ProfileSide::kWheel), TrackParameters{}, WheelSide::kLeft),
               std::invalid_argument);
  TrackParameters bad;
  bad.gauge = std::nan("");
  try {
    PlacedRail(uic60(), bad, WheelSide::kLeft);
    FAIL() << "NaN gauge accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gauge"), std::string::npos);
  }
  EXPECT_THROW(parse_inclination("1:x"), std::invalid_argument);
  EXPECT_NEAR(parse_inclination("1:20"), std::atan(0.05), 1e-15);
}

}  // namespace
}  // namespace wrc
