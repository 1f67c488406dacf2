// SPDX-License-Identifier: Apache-2.0
/// @file
/// brent_root: converges to the tolerance on a smooth root, and reports (never hides) running out
/// of iterations: converged = false, a bracket that still holds the root, and require_converged()
/// throwing a message that names the interval and the iteration count.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/numerics/brent.hpp"

namespace {

// x^2 - 2 on [0, 2]: root sqrt(2); tolerance 1e-12 m, so |x - sqrt(2)| <= 1e-12 (the bracket
// half-width at exit is at most tol1 = 2e-16 |x| + tol / 2).
TEST(BrentRoot, ConvergesToTolerance) {
  auto f = [](double x) { return x * x - 2.0; };
  const wrc::RootResult r = wrc::brent_root(f, 0.0, 2.0, f(0.0), f(2.0), 1e-12);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x, std::sqrt(2.0), 1e-12);
  EXPECT_LE(r.bracket_high - r.bracket_low, 2e-12);
  EXPECT_DOUBLE_EQ(wrc::require_converged(r, "sqrt(2)"), r.x);
}

// x^3 - 0.027 on [0, 1] (root 0.3) with 2 iterations and tolerance 1e-15: two secant or
// interpolation steps on a cubic cannot shrink a unit bracket to 1e-15, so the search must say it
// did not converge; the bracket it reports must still contain the root.
TEST(BrentRoot, ReportsNonConvergence) {
  auto f = [](double x) { return x * x * x - 0.027; };
  const wrc::RootResult r = wrc::brent_root(f, 0.0, 1.0, f(0.0), f(1.0), 1e-15, 2);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.evaluations, 2);
  EXPECT_DOUBLE_EQ(r.interval_low, 0.0);
  EXPECT_DOUBLE_EQ(r.interval_high, 1.0);
  EXPECT_LE(r.bracket_low, 0.3);
  EXPECT_GE(r.bracket_high, 0.3);
  try {
    (void)wrc::require_converged(r, "cube root test");
    FAIL() << "require_converged accepted a non-converged root";
  } catch (const wrc::RootNotConvergedError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cube root test: Brent's method did not converge in 2 iterations on [0, 1]"),
              std::string::npos)
        << what;
  }
}

}  // namespace
