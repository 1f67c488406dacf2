// SPDX-License-Identifier: Apache-2.0
// Contact area of the paper's figures 1-3: distance between the undeformed surfaces along the
// common normal on a grid of the common tangent plane E, and the region where it is below eps0.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/geometry/contact_area.hpp"
#include "core/profile/profile_factory.hpp"

namespace wrc {
namespace {

constexpr double kLambda = 0.05;  // cone slope of the analytic wheel
constexpr double kRho = 0.1;      // circular rail head radius [m]

// Conic wheel on a circular rail head; gauge 1.5 m at the top of rail and no inclination put the
// crown tops right below the taping lines (as in geometry_cone_circle_test.cpp).
WheelsetGeometry cone_on_circle() {
  TrackParameters t;
  t.gauge = 1.5;
  t.gauge_depth = 0.0;
  t.inclination = 0.0;
  return WheelsetGeometry(make_profile("conic:0.05", ProfileSide::kWheel),
                          make_profile("circle:0.1", ProfileSide::kRail), t);
}

WheelsetGeometry s1002_on_uic60() {
  return WheelsetGeometry(make_profile("S1002", ProfileSide::kWheel), make_profile("UIC60", ProfileSide::kRail));
}

WheelsetPose make_pose(double y, double roll, double yaw) {
  WheelsetPose p;
  p.y = y;
  p.z = 0.46;
  p.roll = roll;
  p.yaw = yaw;
  return p;
}

// Analytic limit. Near P the gap is h = A xi^2 + B eta^2 (A = wheel rolling curvature / 2, B =
// (wheel + rail lateral curvature) / 2), so {h < eps0} is an ellipse with semi-axes
// a = sqrt(eps0/A), b = sqrt(eps0/B) and area pi eps0 / sqrt(A B).
// Tolerances, computed below:
//  * grid: the same summary applied to the exact quadratic sampled on the same grid measures the
//    discretisation error exactly; it must itself stay within its a-priori bound. The chord ends
//    are interpolated quadratically, exact for this gap, so only the column sum's tips remain: the
//    chord is ~ 2b sqrt(2t/a) near each tip (t the distance from it), whose sampled sum misses
//    |Hurwitz zeta(-1/2, .)| <= 0.2079 (attained when the tip lies on a node, as here: a / h_xi = 32)
//    times 2b sqrt(2/a) h_xi^1.5 per tip. The extents come from the
//    row and column through P (nodes: odd grid), exact for the quadratic up to round-off.
//  * higher-order terms: circle rail eta^4/(8 rho^3) and wheel rolling circle xi^4/(8 Rn^3) are
//    relative b^2/(4 rho^2) and a^2/(4 Rn^2) of the quadratic; the cone radius changing across eta,
//    A(eta) = A (1 + lambda eta / R), is odd in eta and changes the area only at second order,
//    (lambda b / R)^2. The area scales like 1/(1 + relative gap error), the semi-axes like its
//    square root; a factor 2 of margin.
TEST(GeometryContactArea, ConeOnCircleMatchesHertzEllipse) {
  const WheelsetGeometry g = cone_on_circle();
  const double eps0 = 5e-6;
  for (double y : {0.0, 0.003}) {
    for (double roll : {0.0, 0.002}) {
      const WheelsetPose pose = make_pose(y, roll, 0.0);
      const auto cp = g.common_point(WheelSide::kLeft, pose);
      ASSERT_TRUE(cp.has_value());
      const double A = cp->relative_curvature_rolling();
      const double B = cp->relative_curvature_lateral();
      const double a = std::sqrt(eps0 / A), b = std::sqrt(eps0 / B);
      ContactAreaOptions o;
      o.n_xi = 81;
      o.n_eta = 81;
      o.half_width_xi = 1.25 * a;
      o.half_width_eta = 1.25 * b;
      const ContactArea area = compute_contact_area(g, WheelSide::kLeft, pose, o);
      const ContactAreaSummary s = area.summary(eps0);

      // The exact quadratic on the same grid.
      ContactAreaGrid quad = area.grid;
      for (size_t j = 0; j < quad.eta.size(); ++j)
        for (size_t i = 0; i < quad.xi.size(); ++i)
          quad.distance[j * quad.xi.size() + i] = A * quad.xi[i] * quad.xi[i] + B * quad.eta[j] * quad.eta[j];
      const ContactAreaSummary q = quad.summary(eps0);

      const double exact = M_PI * eps0 / std::sqrt(A * B);
      const double h_xi = quad.xi[1] - quad.xi[0];
      // Next term of the tip expansion (chord ~ c sqrt(t) (1 - t/(4a))): relative h_xi / a at most.
      const double grid_bound = 2 * 0.21 * 2 * b * std::sqrt(2 / a) * std::pow(h_xi, 1.5) * (1 + h_xi / a);
      const double radius_n = 1 / (2 * A);
      const double r = cp->rolling_radius;
      const double rel_geom = 2 * (b * b / (4 * kRho * kRho) + a * a / (4 * radius_n * radius_n) +
                                   std::pow(kLambda * b / r, 2));

      EXPECT_NEAR(q.area, exact, grid_bound) << "quadratic grid, y=" << y << " roll=" << roll;
      EXPECT_NEAR(s.area, q.area, rel_geom * exact + 1e-6 * exact) << "y=" << y << " roll=" << roll;
      EXPECT_NEAR(s.area, exact, grid_bound + rel_geom * exact) << "y=" << y << " roll=" << roll;
      EXPECT_EQ(s.patch_count(), 1);
      EXPECT_FALSE(s.truncated);
      // Extents: the quadratic grid's are exact (round-off); the geometry's within half the relative
      // gap error of them.
      EXPECT_NEAR(q.xi_max, a, 1e-12);
      EXPECT_NEAR(q.eta_max, b, 1e-12);
      const double tol_xi = 0.5 * rel_geom * a + 1e-12, tol_eta = 0.5 * rel_geom * b + 1e-12;
      EXPECT_NEAR(s.xi_max, a, tol_xi);
      EXPECT_NEAR(-s.xi_min, a, tol_xi);
      EXPECT_NEAR(s.eta_max, b, tol_eta);
      EXPECT_NEAR(-s.eta_min, b, tol_eta);
      // Symmetric region: centroid at P to the grid's symmetry (round-off) and the cubic term.
      EXPECT_NEAR(s.xi_centroid, 0.0, 1e-9);
      EXPECT_NEAR(s.eta_centroid, 0.0, 1e-3 * b);
      std::printf("y=%g roll=%g: a=%.4f mm b=%.4f mm area %.6e exact %.6e quad-grid %.6e (grid bound %.2e, "
                  "geometric %.2e); xi_max-a %.2e eta_max-b %.2e (tol %.2e, %.2e)\n",
                  y, roll, a * 1e3, b * 1e3, s.area, exact, q.area, grid_bound, rel_geom * exact, s.xi_max - a,
                  s.eta_max - b, tol_xi, tol_eta);
    }
  }
}

// Single potential common point: the surfaces touch only at P, so the distance along the normal is
// zero at P (the centre node of an odd grid; intersection tolerance 1e-12 m, so 1e-10 m) and
// strictly positive at every other node where both surfaces exist. The minimum along C (curve of
// the paper's left plots) is zero at P and non-negative elsewhere.
TEST(GeometryContactArea, DistanceZeroAtCommonPointPositiveElsewhere) {
  struct Case {
    WheelsetGeometry geometry;
    double y;
  };
  const Case cases[] = {{cone_on_circle(), 0.002}, {s1002_on_uic60(), 0.002}, {s1002_on_uic60(), -0.003}};
  for (const Case& c : cases) {
    for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
      const WheelsetPose pose = make_pose(c.y, 0.0, 0.0);
      const auto points = c.geometry.potential_points(side, pose);
      ASSERT_EQ(points.size(), 1u) << side_name(side) << " y=" << c.y;
      ContactAreaOptions o;
      o.half_width_xi = 0.01;
      const ContactArea area = compute_contact_area(c.geometry, side, pose, o);
      const size_t ci = area.grid.xi.size() / 2, cj = area.grid.eta.size() / 2;
      EXPECT_NEAR(area.grid.at(ci, cj), 0.0, 1e-10);
      int valid = 0;
      for (size_t j = 0; j < area.grid.eta.size(); ++j) {
        for (size_t i = 0; i < area.grid.xi.size(); ++i) {
          const double d = area.grid.at(i, j);
          if (std::isnan(d) || (i == ci && j == cj)) continue;
          ++valid;
          if (!(d > 0)) {
            ADD_FAILURE() << side_name(side) << " y=" << c.y << " node (" << area.grid.xi[i] << ", "
                          << area.grid.eta[j] << "): " << d;
          }
        }
      }
      // Most of the +-20 mm lateral range lies over the rail head.
      EXPECT_GT(valid, static_cast<int>(area.grid.distance.size() / 2));
      // A point of E straight away from P: its distance grows (quadratically) with the offset.
      EXPECT_GT(normal_distance(c.geometry, area, 0.002, 0.0), normal_distance(c.geometry, area, 0.001, 0.0));
      // The distance along C relative to the common point.
      const auto locus = c.geometry.locus(side, pose);
      double smallest = std::numeric_limits<double>::infinity();
      for (const auto& sample : sample_locus_distance(locus, points[0].distance, 2001))
        if (!std::isnan(sample.distance)) smallest = std::min(smallest, sample.distance);
      EXPECT_GE(smallest, -1e-12);
      EXPECT_LT(smallest, 1e-6);  // the 2001 samples pass within a few um of P
    }
  }
}

// S1002 / UIC60 at y = 5 mm, roll 0.3 mrad: two local minima of the distance along C, the common
// point on the tread root (s ~ -17.7 mm) and one on the flange root (s ~ -28.6 mm) about 2.2 um
// higher, with a maximum about 43 um above P between them. Below the second minimum's distance the
// area is one patch around P; between it and the maximum there are two patches, each holding one
// projected minimum; well above the maximum one merged patch.
TEST(GeometryContactArea, TwoSeparatePatchesNearFlangeRoot) {
  const WheelsetGeometry g = s1002_on_uic60();
  const WheelsetPose pose = make_pose(0.005, 0.0003, 0.0);
  ContactAreaOptions o;
  o.n_xi = 121;
  o.n_eta = 241;
  o.half_width_xi = 0.008;
  o.half_width_eta = 0.016;
  const ContactArea area = compute_contact_area(g, WheelSide::kLeft, pose, o);
  ASSERT_EQ(area.minima.size(), 2u);
  const ProjectedMinimum& flange = area.minima[0];  // ordered by s: flange side first
  EXPECT_EQ(area.minima[1].distance, 0.0);
  const double d2 = flange.distance;
  ASSERT_GT(d2, 1e-6);
  ASSERT_LT(d2, 4e-6);

  // The gap at the second minimum measured along n instead of vertically: for locally parallel
  // surfaces with normal angle gamma2 (contact angle there) seen along n at angle gamma1 (contact
  // angle at P) the gap is d2 cos(gamma2) / cos(gamma2 - gamma1). The grid's smallest value in that
  // patch lies above it by at most A (h_xi/2)^2 + B (h_eta/2)^2 (+ the second-order error of the
  // parallel-plane estimate, (gamma2-gamma1)^2 relative).
  const auto points = g.potential_points(WheelSide::kLeft, pose);
  const ContactPoint& second = points.front();
  ASSERT_TRUE(second.is_minimum);
  const double g1 = area.common.contact_angle, g2 = second.contact_angle;
  const double d2n = d2 * std::cos(g2) / std::cos(g2 - g1);

  const ContactAreaSummary below = area.summary(0.5 * d2n);
  EXPECT_EQ(below.patch_count(), 1);
  EXPECT_LT(below.eta_min, 0.0);
  EXPECT_GT(below.eta_max, 0.0);  // the patch around P

  for (double eps0 : {1.5 * d2n, 10e-6, 25e-6}) {
    const ContactAreaSummary s = area.summary(eps0);
    ASSERT_EQ(s.patch_count(), 2) << "eps0=" << eps0;
    EXPECT_FALSE(s.truncated);
    const ContactAreaPatch& p_flange = s.patches[0];  // smaller eta: flange side of the left wheel
    const ContactAreaPatch& p_tread = s.patches[1];
    EXPECT_LT(p_flange.eta_max, p_tread.eta_min);
    EXPECT_GE(flange.eta, p_flange.eta_min);
    EXPECT_LE(flange.eta, p_flange.eta_max);
    EXPECT_GE(0.0, p_tread.eta_min);
    EXPECT_LE(0.0, p_tread.eta_max);
    EXPECT_NEAR(s.area, p_flange.area + p_tread.area, 1e-15);
    const double h_xi = area.grid.xi[1] - area.grid.xi[0], h_eta = area.grid.eta[1] - area.grid.eta[0];
    const double excess = second.relative_curvature_rolling() * 0.25 * h_xi * h_xi +
                          second.relative_curvature_lateral() * 0.25 * h_eta * h_eta;
    EXPECT_GE(p_flange.min_distance, d2n * (1 - std::pow(g2 - g1, 2)));
    EXPECT_LE(p_flange.min_distance, d2n * (1 + std::pow(g2 - g1, 2)) + excess);
    EXPECT_NEAR(p_tread.min_distance, 0.0, 1e-10);
  }
  const ContactAreaSummary merged = area.summary(100e-6);
  EXPECT_EQ(merged.patch_count(), 1);
  EXPECT_LT(merged.eta_min, flange.eta);
  std::printf("second minimum %.4f um vertical, %.4f um along n; patches at 0.5/1.5x: %d/%d\n", d2 * 1e6,
              d2n * 1e6, below.patch_count(), area.summary(1.5 * d2n).patch_count());
}

// Mirror symmetry: the right wheel at (-y, -roll, -yaw) is the mirror image (track y -> -y) of the
// left wheel at (y, roll, yaw); E's lateral axis t2 = n x t1 points towards +y for both, so the
// right grid equals the left one with eta mirrored. The two computations are independent
// (mirrored rail, sigma = -1 in the wheel), so agreement is to the intersection tolerance
// (1e-12 m each, 1e-11 m on the difference allowing for the Newton/Brent stopping points).
TEST(GeometryContactArea, MirrorSymmetry) {
  const WheelsetGeometry g = s1002_on_uic60();
  struct Pose {
    double y, roll, yaw;
  };
  for (const Pose& p : {Pose{0.005, 0.0003, 0.003}, Pose{-0.004, 0.001, -0.002}, Pose{0.009, -0.0005, 0.006}}) {
    const ContactArea left = compute_contact_area(g, WheelSide::kLeft, make_pose(p.y, p.roll, p.yaw));
    const ContactArea right = compute_contact_area(g, WheelSide::kRight, make_pose(-p.y, -p.roll, -p.yaw));
    EXPECT_NEAR(left.normal.x(), right.normal.x(), 1e-12);
    EXPECT_NEAR(left.normal.y(), -right.normal.y(), 1e-12);
    EXPECT_NEAR(left.normal.z(), right.normal.z(), 1e-12);
    EXPECT_NEAR(left.t2.y(), right.t2.y(), 1e-12);
    const size_t nx = left.grid.xi.size(), ny = left.grid.eta.size();
    int compared = 0;
    for (size_t j = 0; j < ny; ++j) {
      for (size_t i = 0; i < nx; ++i) {
        const double dl = left.grid.at(i, j), dr = right.grid.at(i, ny - 1 - j);
        if (std::isnan(dl) || std::isnan(dr)) {
          EXPECT_EQ(std::isnan(dl), std::isnan(dr)) << "node " << i << "," << j;
          continue;
        }
        ++compared;
        if (std::fabs(dl - dr) > 1e-11) {
          ADD_FAILURE() << "y=" << p.y << " node " << i << "," << j << ": " << dl << " vs " << dr;
        }
      }
    }
    EXPECT_GT(compared, static_cast<int>(nx * ny / 2));
    for (double eps0 : {25e-6, 150e-6}) {
      const ContactAreaSummary sl = left.summary(eps0), sr = right.summary(eps0);
      EXPECT_EQ(sl.patch_count(), sr.patch_count());
      EXPECT_NEAR(sl.area, sr.area, 1e-12);
      EXPECT_NEAR(sl.eta_min, -sr.eta_max, 1e-9);
      EXPECT_NEAR(sl.xi_max, sr.xi_max, 1e-9);
    }
  }
}

// Bad options and a wheel off its rail are reported, never silently computed.
TEST(GeometryContactArea, RejectsBadInput) {
  const WheelsetGeometry g = s1002_on_uic60();
  ContactAreaOptions o;
  o.n_xi = 1;
  EXPECT_THROW(compute_contact_area(g, WheelSide::kLeft, make_pose(0, 0, 0), o), std::invalid_argument);
  o = ContactAreaOptions{};
  o.half_width_eta = 0;
  EXPECT_THROW(compute_contact_area(g, WheelSide::kLeft, make_pose(0, 0, 0), o), std::invalid_argument);
  EXPECT_THROW(compute_contact_area(g, WheelSide::kLeft, make_pose(0.3, 0, 0)), std::runtime_error);  // 30 cm: off the rail
  ContactAreaGrid bad;
  bad.xi = {0, 1};
  bad.eta = {0, 1};
  bad.distance = {0, 0, 0};
  EXPECT_THROW(bad.summary(1e-5), std::invalid_argument);
}

}  // namespace
}  // namespace wrc
