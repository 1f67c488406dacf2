// SPDX-License-Identifier: Apache-2.0
// The default spline model on the rigid manifold against the exact geometry (S1002/UIC60): at the
// exact rigid wheelset (roll and height solved for both wheels touching) for |y| <= 6 mm and
// |yaw| <= 3 mrad, at least 1 mm in y from every jump of either wheel's exact common point, the
// spline model's and the one-point model's evaluate() on the same pose with the same normal loads:
// per wheel the contact point's s, contact angle, rolling radius, the semi-axes a and b, the
// fitted gap (z_touch against the exact height), and the lateral force by which the fitted normal
// and the gradient of the fitted z disagree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/models/contact_model_factory.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

struct Stat {
  double sum_sq = 0, max = 0;
  int n = 0;
  void add(double e) {
    e = std::abs(e);
    sum_sq += e * e;
    max = std::max(max, e);
    ++n;
  }
  double rms() const { return n ? std::sqrt(sum_sq / n) : 0.0; }
};

struct ManifoldErrors {
  Stat s, angle, radius, a, b, z, lateral_mismatch;
  int points = 0, skipped = 0;
};

// Lateral shifts at which either wheel's exact rigid common point jumps at yaw (a step of more
// than 1 mm in s between rigid solutions 20 um apart) over [-6, 6] mm.
std::vector<double> manifold_jumps(const RigidWheelsetSolver& solver, double yaw) {
  std::vector<double> jumps;
  const double h = 2e-5;
  RigidContact last = solver.solve(-0.006, yaw);
  for (double y = -0.006 + h; y <= 0.006 + 1e-12; y += h) {
    const RigidContact now = solver.solve(y, yaw, last);
    if (std::abs(now.left().s - last.left().s) > 1e-3 || std::abs(now.right().s - last.right().s) > 1e-3)
      jumps.push_back(y - 0.5 * h);
    last = now;
  }
  return jumps;
}

const ManifoldErrors& measured() {
  static const ManifoldErrors errors = [] {
    ManifoldErrors out;
    const auto geometry = test::s1002_uic60_geometry();
    const auto spline = make_contact_model("spline", geometry, {}, ContactModelData{test::default_spline_fit().model});
    const auto exact = make_contact_model("onepoint", geometry);
    const RigidWheelsetSolver solver(*geometry);
    for (double yaw : {-0.003, -0.0015, 0.0, 0.0015, 0.003}) {
      const std::vector<double> jumps = manifold_jumps(solver, yaw);
      for (double y = -0.006; y <= 0.006 + 1e-12; y += 1e-4) {
        const bool near = std::any_of(jumps.begin(), jumps.end(), [&](double j) { return std::abs(y - j) < 1e-3; });
        if (near) {
          ++out.skipped;
          continue;
        }
        ContactQuery q;
        q.pose = solver.solve(y, yaw).pose;
        q.speed = 30.0;
        q.spin_rate = 30.0 / 0.46;
        q.y_dot = 0.01;
        q.normal_load = {77e3, 77e3};
        const ContactResult r = spline->evaluate(q), e = exact->evaluate(q);
        if (r.patches.size() != 2 || e.patches.size() != 2) {
          ++out.skipped;
          continue;
        }
        ++out.points;
        for (size_t k = 0; k < 2; ++k) {
          const ContactPatch &p = r.patches[k], &x = e.patches[k];
          out.s.add(p.point.s - x.point.s);
          out.angle.add(p.point.contact_angle - x.point.contact_angle);
          out.radius.add(p.point.rolling_radius - x.point.rolling_radius);
          out.a.add(p.a / x.a - 1.0);
          out.b.add(p.b / x.b - 1.0);
          out.z.add(r.wheels[k].gap);  // the exact rigid pose: both exact gaps are 0
          // The constraint's lateral reaction per vertical load is d gap / dy = -dz_touch/dy; the
          // creep frame's normal has n_y / n_z: their difference times the vertical load.
          const double vertical = p.normal_force * p.point.normal.z();
          out.lateral_mismatch.add(vertical * (r.wheels[k].gap_gradient[0] - p.point.normal.y() / p.point.normal.z()));
        }
      }
    }
    std::printf("[ measured ] spline on the rigid manifold, >= 1 mm from jumps, |yaw| <= 3 mrad: %d poses (%d left out)\n",
                out.points, out.skipped);
    auto line = [](const char* what, const Stat& s, double scale, const char* unit) {
      std::printf("[ measured ]   %-26s rms %8.4g  max %8.4g %s\n", what, s.rms() * scale, s.max * scale, unit);
    };
    line("s", out.s, 1e3, "mm");
    line("contact angle", out.angle, 1e3, "mrad");
    line("rolling radius", out.radius, 1e6, "um");
    line("a", out.a, 1e2, "%");
    line("b", out.b, 1e2, "%");
    line("z (gap at the exact pose)", out.z, 1e6, "um");
    line("normal vs grad z, lateral", out.lateral_mismatch, 1e-3, "kN");
    return out;
  }();
  return errors;
}

// The targets of the spline model where its inputs of the creep forces are used (measured with
// the default model, 10 x 2 x 2 intervals per branch, transition 0.2 mm; before the branch fits,
// one fit across the jumps gave s 0.43 mm, angle 4.0 mrad, radius 49 um, a 2.8 %, b 5.2 %, the
// lateral mismatch 2.4 kN): s within 0.05 mm (measured 2.4 um), contact angle 0.5 mrad (0.32,
// from the gradient of the fitted z), rolling radius 2 um (0.13), a and b 2 % (0.96 %: Hertz's
// coefficients m and n are smooth on a branch, the fit leaves little), the fitted z within
// 0.5 um rms / 5 um max (0.002 / 0.009 um), and the creep frame's normal consistent with the
// constraint's gradient to 0.1 kN of lateral force (both from one fit: 4e-15 kN).
TEST(SplineManifoldAccuracy, ContinuousParametersAgreeWithTheExactGeometry) {
  const ManifoldErrors& e = measured();
  EXPECT_GT(e.points, 250);
  EXPECT_LT(e.s.max, 5e-5);
  EXPECT_LT(e.angle.max, 5e-4);
  EXPECT_LT(e.radius.max, 2e-6);
  EXPECT_LT(e.a.max, 0.02);
  EXPECT_LT(e.b.max, 0.02);
  EXPECT_LT(e.z.rms(), 5e-7);
  EXPECT_LT(e.z.max, 5e-6);
  EXPECT_LT(e.lateral_mismatch.max, 100.0);
}

}  // namespace
}  // namespace wrc
