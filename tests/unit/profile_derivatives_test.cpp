// SPDX-License-Identifier: Apache-2.0
// Every profile's slope and second derivative against central finite differences of its height
// (and of its slope), away from breakpoints where the second derivative jumps by design.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/profile/profile_factory.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {
namespace {

// Checks slope and second derivative on a grid of 2000 points with Richardson-extrapolated central
// differences (steps h and 2h, h = 2e-6 m / (1 + |F'|)): truncation error O(h^4 f^(5)), and f^(5)
// grows like (1 + F'^2)^4 on near-vertical arcs, hence the smaller step there; rounding error is
// about eps |F| / h < 1e-10 in the slope and eps |F'| / h < 1e-8 |F'| in the second derivative. The
// tolerances are 1e-6 (slope) and 1e-5 (second derivative) relative plus absolute floors 1e-7 and
// 1e-2 [1/m] (typical second derivatives are 1 to 1e6 1/m).
void check_derivatives(const Profile& p, double skip_near_breakpoint) {
  const std::vector<double> breaks = p.breakpoints();
  const double h0 = 2e-6;
  const double a = p.lower() + 3 * h0;
  const double b = p.upper() - 3 * h0;
  int checked = 0;
  for (int i = 0; i <= 2000; ++i) {
    const double s = a + (b - a) * i / 2000.0;
    const bool near_break = std::any_of(breaks.begin(), breaks.end(), [&](double x) {
      return std::fabs(x - s) < skip_near_breakpoint;
    });
    if (near_break) continue;
    const ProfileSample c = p.evaluate(s);
    const double h = h0 / (1.0 + std::fabs(c.slope));
    const ProfileSample l1 = p.evaluate(s - h);
    const ProfileSample r1 = p.evaluate(s + h);
    const ProfileSample l2 = p.evaluate(s - 2 * h);
    const ProfileSample r2 = p.evaluate(s + 2 * h);
    const double fd_slope = (8 * (r1.height - l1.height) - (r2.height - l2.height)) / (12 * h);
    const double fd_curv = (8 * (r1.slope - l1.slope) - (r2.slope - l2.slope)) / (12 * h);
    EXPECT_NEAR(c.slope, fd_slope, 1e-7 + 1e-6 * std::fabs(c.slope)) << p.name() << " s=" << s;
    EXPECT_NEAR(c.second_derivative, fd_curv, 1e-2 + 1e-5 * std::fabs(c.second_derivative))
        << p.name() << " s=" << s;
    ++checked;
  }
  EXPECT_GT(checked, 1500) << p.name();
}

TEST(ProfileDerivatives, AnalyticProfilesMatchFiniteDifferences) {
  check_derivatives(*make_profile("S1002", ProfileSide::kWheel), 5e-6);
  check_derivatives(*make_profile("UIC60", ProfileSide::kRail), 5e-6);
  check_derivatives(*make_profile("UIC60-MB", ProfileSide::kRail), 5e-6);
  check_derivatives(*make_profile("conic:0.1", ProfileSide::kWheel), 5e-6);
  check_derivatives(*make_profile("circle:0.3", ProfileSide::kRail), 5e-6);
  check_derivatives(*make_profile("circle:0.02", ProfileSide::kRail), 5e-6);
}

}  // namespace
}  // namespace wrc

namespace wrc {
namespace {

// The file splines (shipped Manchester files, Apache-2.0, see profiles/README.md): C2 cubics, so
// the same finite-difference checks hold everywhere (they list no breakpoints).
TEST(ProfileDerivatives, FileSplinesMatchFiniteDifferences) {
  const std::string dir = WRC_PROFILES_DIR;
  check_derivatives(*make_profile(dir + "/MBench_S1002_v3.prw", ProfileSide::kWheel), 0.0);
  check_derivatives(*make_profile(dir + "/MBench_UIC60_v3.prr", ProfileSide::kRail), 0.0);
  ProfileFileOptions options;
  options.built_in_cant = 0.025;
  check_derivatives(*make_profile(dir + "/MBench_UIC60_v3.ban", ProfileSide::kRail, options), 0.0);
}

}  // namespace
}  // namespace wrc
