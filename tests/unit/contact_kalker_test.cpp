// SPDX-License-Identifier: Apache-2.0
// Unit tests of Kalker's coefficients and the linear theory (services/core/contact).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/contact/kalker_coefficients.hpp"
#include "core/contact/linear_creep.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// Verifies the interpolation to nu = 0.28 against the reference values of docs/contact-mechanics.md
// ("Kalker's linear theory and coefficients"), which were computed with CONTACT's rule (quadratic Lagrange
// in 1/C). They have 4 significant digits: rounding is <= 5e-4, so an absolute tolerance of 1e-3 detects
// any different rule (linear interpolation of C in nu would give e.g. C11(a/b = 1) = 4.249, off by 0.023).
TEST(KalkerCoefficients, InterpolatedToNu028MatchesReference) {
  struct Row { double a_over_b, c11, c22, c23; };
  const Row rows[] = {{1.0, 4.226, 3.705, 1.488},
                      {1 / 0.7, 4.644, 4.261, 1.975},
                      {1 / 0.5, 5.204, 4.971, 2.657},
                      {1 / 0.2, 7.892, 8.308, 6.759},
                      {1 / 0.1, 11.83, 13.11, 14.95}};
  for (const Row& r : rows) {
    const auto c = wrc::kalker_coefficients(r.a_over_b, 0.28);
    const double tol = r.c11 > 10 ? 1e-2 : 1e-3;  // the b/a = 0.1 row has one digit less
    EXPECT_NEAR(c.c11, r.c11, tol) << "a/b " << r.a_over_b;
    EXPECT_NEAR(c.c22, r.c22, tol) << "a/b " << r.a_over_b;
    EXPECT_NEAR(c.c23, r.c23, tol) << "a/b " << r.a_over_b;
  }
}

// Verifies that table nodes are reproduced exactly (to rounding, 1e-12) at nu = 0, 0.25, 0.5, that
// g is interpolated linearly between rows (the midpoint of rows a/b = 0.5 and 0.6 at nu = 0 is the mean),
// and that C33 (lower confidence) comes from its own table (b/a = 0.5, nu = 0.25 -> 0.819).
TEST(KalkerCoefficients, TableNodesAndLinearRows) {
  EXPECT_NEAR(wrc::kalker_coefficients(0.3, 0.0).c11, 2.68, 1e-12);
  EXPECT_NEAR(wrc::kalker_coefficients(0.8, 0.25).c23, 1.25, 1e-12);  // the corrected value, not 1.15
  EXPECT_NEAR(wrc::kalker_coefficients(1 / 0.3, 0.5).c22, 7.51, 1e-12);
  EXPECT_NEAR(wrc::kalker_coefficients(2.0, 0.25).c33, 0.819, 1e-12);
  EXPECT_NEAR(wrc::kalker_coefficients(0.55, 0.0).c11, 0.5 * (2.88 + 2.98), 1e-12);
  // between b/a = 0.3 and 0.2 (a/b = 4): linear in b/a = 0.25
  EXPECT_NEAR(wrc::kalker_coefficients(4.0, 0.0).c22, 0.5 * (5.57 + 6.96), 1e-12);
}

// Verifies continuity (1e-9 jump at most across the joins: a/b = 0.1, 1 and b/a = 0.1) and monotonicity
// over a/b = 1e-3 .. 1e3: C11, C22, C23 increase with a/b as in the table, C33 decreases. A jump or a
// wrong branch at the joins (the asymptotes, the swap of the table side) would break one of these.
TEST(KalkerCoefficients, ContinuousAndMonotoneOverWholeRange) {
  for (double join : {0.1, 1.0, 10.0}) {
    const auto lo = wrc::kalker_coefficients(join * (1 - 1e-10), 0.28);
    const auto hi = wrc::kalker_coefficients(join * (1 + 1e-10), 0.28);
    EXPECT_NEAR(lo.c11, hi.c11, 1e-8) << join;
    EXPECT_NEAR(lo.c22, hi.c22, 1e-8) << join;
    EXPECT_NEAR(lo.c23, hi.c23, 1e-8) << join;
    EXPECT_NEAR(lo.c33, hi.c33, 1e-8) << join;
  }
  wrc::KalkerCoefficients prev = wrc::kalker_coefficients(1e-3, 0.28);
  for (int i = 1; i <= 600; ++i) {
    const double g = std::pow(10.0, -3.0 + i / 100.0);
    const auto c = wrc::kalker_coefficients(g, 0.28);
    EXPECT_GE(c.c11, prev.c11) << g;
    EXPECT_GE(c.c22, prev.c22 - 1e-12) << g;
    EXPECT_GT(c.c23, prev.c23) << g;
    EXPECT_LT(c.c33, prev.c33) << g;
    prev = c;
  }
}

// Verifies the a < b asymptotes: at a/b = 1e-3 C11 and C22 are within 0.2 % of pi^2/(4(1-nu)) and pi^2/4
// (the linear join to the g = 0.1 row leaves 1 % of the row's offset, about 0.03 absolute, at g = 1e-3),
// and C23 follows Kalker's sqrt(g)(1 + nu(ln(16/g) - 5)) law scaled to the row (ratio exact to 1e-12 at nu = 0).
TEST(KalkerCoefficients, WideEllipseAsymptotes) {
  const double nu = 0.25;
  const auto c = wrc::kalker_coefficients(1e-3, nu);
  EXPECT_NEAR(c.c11, kPi * kPi / (4 * (1 - nu)), 2e-3 * c.c11);
  EXPECT_NEAR(c.c22, kPi * kPi / 4, 2e-3 * c.c22);
  const auto c0 = wrc::kalker_coefficients(1e-3, 0.0);
  EXPECT_NEAR(c0.c23 / wrc::kalker_coefficients(0.1, 0.0).c23, std::sqrt(1e-3 / 0.1), 1e-12);
}

// Verifies the error contract: a/b <= 0, NaN or nu outside [0, 0.5] throw naming the value.
TEST(KalkerCoefficients, RejectsInvalidInput) {
  EXPECT_THROW(wrc::kalker_coefficients(0.0, 0.28), std::invalid_argument);
  EXPECT_THROW(wrc::kalker_coefficients(std::numeric_limits<double>::quiet_NaN(), 0.28), std::invalid_argument);
  try {
    wrc::kalker_coefficients(1.0, 0.7);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nu = 0.7"), std::string::npos) << e.what();
  }
}

// Verifies the linear theory's forces against numbers worked out by hand from Kalker's published
// coefficients for a round patch at nu = 0.25 (C11 = 4.12, C22 = 3.67, C23 = 1.47; J.J. Kalker,
// 1967, as tabulated in K.L. Johnson, "Contact Mechanics", 1985), a = b = 5 mm, G = 8.2e10 Pa, so
// G c^2 = 2.05e6 N and G c^3 = 1.025e4 N m. Creepages xi_x = 1e-4, xi_y = -2e-4 (no spin):
//   fx = -G c^2 C11 xi_x = -844.6 N,  fy = -G c^2 C22 xi_y = 1504.7 N,  mz = G c^3 C23 xi_y = -3.0135 N m;
// spin phi = 0.3 1/m alone: fy = -G c^3 C23 phi = -4520.25 N. Bound: the coefficients' three
// digits (0.005 in 1.47: 0.35 %). C33 (the spin moment) has no second source here
// (docs/contact-mechanics.md): only its sign is checked, the moment opposing the spin. The forces
// on the wheel oppose the creepage, and positive spin pushes the wheel to -y.
TEST(KalkerLinearTheory, ForcesOfARoundPatchAgainstKalkersTable) {
  wrc::CreepPatch p;
  p.a = p.b = 5e-3;
  p.poisson = 0.25;
  p.shear_modulus = 8.2e10;
  const auto f = wrc::linear_creep_forces(p, {1e-4, -2e-4, 0.0});
  EXPECT_NEAR(f.fx, -844.6, 0.004 * 844.6);
  EXPECT_NEAR(f.fy, 1504.7, 0.004 * 1504.7);
  EXPECT_NEAR(f.mz, -3.0135, 0.004 * 3.0135);
  const auto spin = wrc::linear_creep_forces(p, {0, 0, 0.3});
  EXPECT_NEAR(spin.fy, -4520.25, 0.004 * 4520.25);
  EXPECT_LT(spin.mz, 0.0);
  EXPECT_EQ(spin.fx, 0.0);
  EXPECT_EQ(f.slip_fraction, 0.0);
  p.a = -1;
  EXPECT_THROW(wrc::linear_creep_forces(p, {0, 0, 0}), std::invalid_argument);
}

}  // namespace
