// SPDX-License-Identifier: Apache-2.0
/// @file
/// brent_root at the edges of what it promises (brent.hpp): a root at either end of the interval
/// is returned as it is, without a single evaluation; a flat root (a triple root, a function that
/// is zero on a whole interval) is still found to the absolute tolerance asked; an interval given
/// high end first is the same interval; and an interval that does not bracket a root (both ends of
/// one sign) is refused with std::invalid_argument, never answered with a point.
///
/// The promise: the search stops when the bracket [b, c] that holds the sign change has half-width
/// at most tol1 = 2e-16 |b| + tol / 2, and returns b, so |x - root| <= 2 tol1 = tol + 4e-16 |x|.
/// The bracket left, [bracket_low, bracket_high], is at most that wide. Every bound below is that
/// one (kRounding = 4e-16 relative), not a looser one.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/numerics/brent.hpp"

namespace {

constexpr double kRounding = 4e-16;  // the relative part of the stopping rule (2 * 2e-16)

// The bound brent_root promises for a root at `root` found to tol.
double promised(double root, double tol) { return tol + kRounding * std::abs(root); }

// A root exactly at a, or exactly at b, is that end: f there is 0, the result is the end itself,
// f(x) = 0, converged, no evaluation (the function is never called), whatever the sign at the
// other end. The counting lambda would notice a call.
TEST(BrentRootCases, RootAtAnEndIsThatEnd) {
  int calls = 0;
  auto f = [&calls](double x) {
    ++calls;
    return (x - 0.25) * (x + 3.0);
  };
  for (const double other : {1.0, -1.0}) {  // f(other) > 0 and f(other) < 0
    const wrc::RootResult low = wrc::brent_root(f, 0.25, other, 0.0, (other - 0.25) * (other + 3.0), 1e-12);
    EXPECT_EQ(low.x, 0.25);
    EXPECT_EQ(low.fx, 0.0);
    EXPECT_TRUE(low.converged);
    EXPECT_EQ(low.evaluations, 0);
    const wrc::RootResult high = wrc::brent_root(f, other, 0.25, (other - 0.25) * (other + 3.0), 0.0, 1e-12);
    EXPECT_EQ(high.x, 0.25);
    EXPECT_EQ(high.fx, 0.0);
    EXPECT_TRUE(high.converged);
    EXPECT_EQ(high.evaluations, 0);
  }
  EXPECT_EQ(calls, 0);
}

// A root very close to an end (1e-13 inside an interval of length 1) is found to the tolerance:
// the interpolation steps must not jump out over it and the safeguard steps of tol1 must reach it.
TEST(BrentRootCases, RootNextToAnEnd) {
  for (const double root : {1e-13, 1.0 - 1e-13}) {
    auto f = [root](double x) { return std::expm1(x - root); };  // exact sign around the root
    const double tol = 1e-15;
    const wrc::RootResult r = wrc::brent_root(f, 0.0, 1.0, f(0.0), f(1.0), tol);
    ASSERT_TRUE(r.converged) << root;
    EXPECT_NEAR(r.x, root, promised(root, tol)) << root;
    EXPECT_LE(r.bracket_low, root);
    EXPECT_GE(r.bracket_high, root);
    if (r.fx != 0.0) {
      EXPECT_LE(r.bracket_high - r.bracket_low, promised(root, tol)) << root;
    }
  }
}

// (x - a)^3: f and f' vanish at the root, so the interpolation steps gain little and the
// function is below 1e-30 within 1e-10 of it; the bisection safeguard must still bring the
// bracket down to the tolerance. x - a is exact near the root (Sterbenz), so the sign of f is
// exact and the promised bound holds without any slack. Tolerances 1e-6 .. 1e-14 and roots at
// different places in [-1, 2]. Brent's method needs more evaluations here than bisection would
// (measured 54 to 142 against bisection's 22 to 48): max_iterations = 400 leaves room, and the
// default of 100 is the next test's case.
TEST(BrentRootCases, TripleRootToTheTolerance) {
  for (const double a : {0.3, -0.7, 1.9, 1.0 / 3.0}) {
    for (const double tol : {1e-6, 1e-10, 1e-14}) {
      auto f = [a](double x) {
        const double d = x - a;
        return d * d * d;
      };
      const wrc::RootResult r = wrc::brent_root(f, -1.0, 2.0, f(-1.0), f(2.0), tol, 400);
      ASSERT_TRUE(r.converged) << "a = " << a << ", tol = " << tol;
      EXPECT_NEAR(r.x, a, promised(a, tol)) << "a = " << a << ", tol = " << tol;
      EXPECT_LE(r.bracket_low, a);
      EXPECT_GE(r.bracket_high, a);
      // The bracket itself shrank to the tolerance (unless f hit 0 exactly, which ends at once).
      if (r.fx != 0.0) {
        EXPECT_LE(r.bracket_high - r.bracket_low, promised(a, tol)) << "a = " << a << ", tol = " << tol;
      }
    }
  }
}

// The same triple root to 1e-14 with the default 100 iterations (it needs 141): the search runs
// out and says so, converged = false, with a bracket that still holds the root and
// require_converged() throwing; never a silent answer.
TEST(BrentRootCases, TripleRootOutOfIterationsIsReported) {
  auto f = [](double x) {
    const double d = x - 0.3;
    return d * d * d;
  };
  const wrc::RootResult r = wrc::brent_root(f, -1.0, 2.0, f(-1.0), f(2.0), 1e-14);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.evaluations, 100);
  EXPECT_LE(r.bracket_low, 0.3);
  EXPECT_GE(r.bracket_high, 0.3);
  EXPECT_THROW((void)wrc::require_converged(r, "triple root"), wrc::RootNotConvergedError);
}

// A function zero on a whole interval [0.2, 0.6] (negative left of it, positive right): every
// point of the interval is a root, so the result must be one of them to the tolerance, with
// f(x) = 0 or a bracket within tol of the flat part; and the same with the interval reversed.
TEST(BrentRootCases, FunctionZeroOnAnInterval) {
  auto f = [](double x) { return x < 0.2 ? x - 0.2 : (x > 0.6 ? x - 0.6 : 0.0); };
  for (const double tol : {1e-3, 1e-9, 1e-14}) {
    for (const bool reversed : {false, true}) {
      const double a = reversed ? 1.0 : -1.0, b = reversed ? -1.0 : 1.0;
      const wrc::RootResult r = wrc::brent_root(f, a, b, f(a), f(b), tol);
      ASSERT_TRUE(r.converged);
      EXPECT_GE(r.x, 0.2 - promised(0.2, tol)) << tol;
      EXPECT_LE(r.x, 0.6 + promised(0.6, tol)) << tol;
      EXPECT_DOUBLE_EQ(r.interval_low, -1.0);
      EXPECT_DOUBLE_EQ(r.interval_high, 1.0);
    }
  }
}

// The interval given high end first is the same search: the same root to the tolerance, and the
// interval reported low end first.
TEST(BrentRootCases, ReversedIntervalIsTheSame) {
  auto f = [](double x) { return std::cos(x) - x; };  // root 0.739085133215160641655...
  const double root = 0.7390851332151607, tol = 1e-13;
  const wrc::RootResult r = wrc::brent_root(f, 2.0, 0.0, f(2.0), f(0.0), tol);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.x, root, promised(root, tol) + 1e-16);  // + the last digit of the reference root
  EXPECT_EQ(r.interval_low, 0.0);
  EXPECT_EQ(r.interval_high, 2.0);
}

// Both ends of one sign (positive, negative; a double root touching zero inside, where a sign
// change never happens): brent_root refuses with std::invalid_argument naming the reason, and
// evaluates nothing.
TEST(BrentRootCases, NonBracketingIntervalIsRefused) {
  int calls = 0;
  auto square = [&calls](double x) {
    ++calls;
    return (x - 0.5) * (x - 0.5);  // double root at 0.5: f >= 0 everywhere
  };
  try {
    (void)wrc::brent_root(square, 0.0, 1.0, square(0.0), square(1.0), 1e-12);
    FAIL() << "a non-bracketing interval was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "brent_root: the interval does not bracket a root");
  }
  auto negative = [](double x) { return -1.0 - x * x; };
  EXPECT_THROW((void)wrc::brent_root(negative, -1.0, 1.0, -2.0, -2.0, 1e-12), std::invalid_argument);
  EXPECT_EQ(calls, 2);  // the two end values computed above, nothing inside
}

}  // namespace
