// SPDX-License-Identifier: Apache-2.0
// The real profile files of the Manchester contact benchmark (profiles/MBench_*; Shackleton &
// Iwnicki, distributed with CONTACT under Apache-2.0) against the analytic profiles, through the
// whole rigid-wheelset geometry.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

const std::string kDir = WRC_PROFILES_DIR;

// The S1002 file on the analytic UIC60 rail reproduces the analytic S1002's rigid-wheelset
// geometry: the file agrees with the formula to 2e-9 m at its points and 7e-7 m between them
// (profile tests), so rolling radii agree within 1 um and the height within 1 um wherever the
// common point does not sit exactly at a jump (the jump position may move by the profile error).
TEST(GeometryManchester, S1002FileMatchesAnalyticS1002) {
  const WheelsetGeometry analytic(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
  const WheelsetGeometry file(make_profile(kDir + "/MBench_S1002_v3.prw", ProfileSide::kWheel),
                              make_profile("UIC60", ProfileSide::kRail));
  const RigidWheelsetSolver a(analytic), f(file);
  int compared = 0;
  for (double y = -0.009; y <= 0.0091; y += 0.00025) {
    const RigidContact ca = a.solve(y, 0.0), cf = f.solve(y, 0.0);
    if (std::fabs(ca.left().s - cf.left().s) > 1e-3 || std::fabs(ca.right().s - cf.right().s) > 1e-3) continue;  // at a jump
    ++compared;
    EXPECT_NEAR(ca.left().rolling_radius, cf.left().rolling_radius, 1e-6) << y;
    EXPECT_NEAR(ca.right().rolling_radius, cf.right().rolling_radius, 1e-6) << y;
    EXPECT_NEAR(ca.pose.z, cf.pose.z, 1e-6) << y;
  }
  EXPECT_GE(compared, 70);
}

// The canted rail files (.prr with its built-in 1:40 cant, .ban the same points mirrored, read with
// an explicit cant) agree with the analytic Manchester variant UIC60-MB placed at 1:40: the file
// head lies within 5 um of the analytic construction (profile tests), so delta_r agrees within a
// few micrometres away from the jumps.
TEST(GeometryManchester, RailFilesMatchAnalyticManchesterVariant) {
  const auto wheel = make_profile("S1002", ProfileSide::kWheel);
  const WheelsetGeometry analytic(wheel, make_profile("UIC60-MB", ProfileSide::kRail));
  ProfileFileOptions canted;
  canted.built_in_cant = std::atan(1.0 / 40.0);
  const WheelsetGeometry prr(wheel, make_profile(kDir + "/MBench_UIC60_v3.prr", ProfileSide::kRail));
  const WheelsetGeometry ban(wheel, make_profile(kDir + "/MBench_UIC60_v3.ban", ProfileSide::kRail, canted));
  EXPECT_NEAR(prr.rail(WheelSide::kLeft).rotation(), 0.0, 1e-15);
  const RigidWheelsetSolver a(analytic), p(prr), b(ban);
  int compared = 0;
  for (double y = -0.008; y <= 0.0081; y += 0.0005) {
    const RigidContact ca = a.solve(y, 0.0), cp = p.solve(y, 0.0), cb = b.solve(y, 0.0);
    EXPECT_NEAR(cp.delta_r(), cb.delta_r(), 1e-9) << y;  // same points, same spline
    if (std::fabs(ca.left().s - cp.left().s) > 1e-3 || std::fabs(ca.right().s - cp.right().s) > 1e-3) continue;
    ++compared;
    EXPECT_NEAR(ca.delta_r(), cp.delta_r(), 1e-5) << y;
    EXPECT_NEAR(ca.pose.z, cp.pose.z, 1e-5) << y;
  }
  EXPECT_GE(compared, 25);
}

// Cross-check with the roll angles of the Manchester benchmark as run by CONTACT (test_mbench:
// yaw = 2.4 mrad per mm of shift; docs/profiles.md, "Profile files"): |roll| = 0.63 mrad at y = 6.0 mm, on the
// tread side of the flange-root jump, and the jump to flange contact between 6.0 and 6.5 mm.
// Tolerance 0.02 mrad: the reference is given to two digits.
TEST(GeometryManchester, RollAngleMatchesBenchmarkBeforeTheFlangeJump) {
  const WheelsetGeometry g(make_profile(kDir + "/MBench_S1002_v3.prw", ProfileSide::kWheel),
                           make_profile(kDir + "/MBench_UIC60_v3.prr", ProfileSide::kRail));
  const RigidWheelsetSolver solver(g);
  const RigidContact at60 = solver.solve(0.0060, 0.0144);
  const RigidContact at65 = solver.solve(0.0065, 0.0156);
  EXPECT_NEAR(std::fabs(at60.pose.roll), 0.63e-3, 0.02e-3);
  EXPECT_LT(at60.left().contact_angle, 0.5);   // flange root, not yet the flank
  EXPECT_GT(at65.left().contact_angle, 1.0);   // on the flange flank (about 66 degrees)
  EXPECT_GT(std::fabs(at65.pose.roll), 4e-3);  // CONTACT: 4.38 mrad; here 4.55 mrad (see docs/profiles.md)
}

// At y = 6.5 mm (flange contact) CONTACT gives |roll| = 4.38 mrad. The flange is steep there, so
// the roll depends strongly on where the rail sits laterally, and that run's rail placement is
// known only to about 0.05 mm (docs/profiles.md). The band is therefore derived, not chosen: the change of
// roll when the wheelset moves 0.05 mm either way at the same yaw (the same as moving the rail),
// plus 0.005 mrad for the reference's rounding to two decimals of a mrad. wrc's 4.55 mrad must lie
// within CONTACT's value +- that band, and the band must stay a fraction of the value (below
// 10 %), or the comparison would say nothing.
TEST(GeometryManchester, RollInFlangeContactWithinThePlacementBand) {
  const WheelsetGeometry g(make_profile(kDir + "/MBench_S1002_v3.prw", ProfileSide::kWheel),
                           make_profile(kDir + "/MBench_UIC60_v3.prr", ProfileSide::kRail));
  const RigidWheelsetSolver solver(g);
  const double yaw = 0.0156;  // 2.4 mrad per mm at 6.5 mm
  const double roll = std::fabs(solver.solve(0.0065, yaw).pose.roll);
  const double inner = std::fabs(solver.solve(0.0065 - 0.05e-3, yaw).pose.roll);
  const double outer = std::fabs(solver.solve(0.0065 + 0.05e-3, yaw).pose.roll);
  const double band = std::max(std::fabs(outer - roll), std::fabs(roll - inner)) + 0.005e-3;
  // Today: roll 4.547 mrad, 4.248 and 4.810 mrad at -+0.05 mm, band 0.303 mrad.
  EXPECT_LT(band, 0.1 * 4.38e-3);
  EXPECT_NEAR(roll, 4.38e-3, band) << "inner " << inner << ", outer " << outer;
  // wrc's own value as docs/profiles.md quotes it (4.55 mrad, to the 0.005 mrad of its last digit).
  EXPECT_NEAR(roll, 4.55e-3, 0.005e-3);
}

}  // namespace
}  // namespace wrc
