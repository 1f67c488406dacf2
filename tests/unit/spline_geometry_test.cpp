// SPDX-License-Identifier: Apache-2.0
// The fitted spline contact geometry of S1002 on UIC60 against the exact geometry: the paper's
// accuracy claim for a 10 x 2 x 2 grid, mirror symmetry of the two wheels, the vertical
// displacement's gradient against finite differences of the exact geometry, the automatic jump
// location against a dense scan, and what the weights and the knots do.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "core/spline/spline_validation.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

using test::default_spline_fit;
using test::quick_spline_fit;
using test::quick_spline_options;
using test::s1002_uic60_geometry;

// RMS of z over both wheels' continuous region.
double z_rms(const SplineAccuracy& a) {
  const FieldError& l = a.wheels[0].continuous[kFieldZ];
  const FieldError& r = a.wheels[1].continuous[kFieldZ];
  return std::sqrt((l.rms_error * l.rms_error * l.samples + r.rms_error * r.rms_error * r.samples) /
                   (l.samples + r.samples));
}

// The paper (section 4): with a 10 x 2 x 2 grid in (y, roll, yaw) the vertical displacement z is
// approximated to about 0.5 um. Read as an RMS on the tread, with a 5 um bound on the largest
// error, at validation points that are not samples (midpoints), outside +-0.5 mm of each jump of
// the exact common point. The default model (10 x 2 x 2, cubic, graded knots) meets both with a
// margin (measured: 0.36 um RMS, 3.0 um max), and leaves out less than a quarter of the points.
TEST(SplineGeometry, DefaultModelMeetsThePapersAccuracy) {
  const SplineFitOptions options;
  ASSERT_EQ(options.intervals, (std::array<int, 3>{10, 2, 2}));
  const SplineAccuracy a = validate_spline_geometry(*s1002_uic60_geometry(), *default_spline_fit().model, options);
  const double max = std::max(a.wheels[0].continuous[kFieldZ].max_error, a.wheels[1].continuous[kFieldZ].max_error);
  std::cout << "z: rms " << z_rms(a) * 1e6 << " um, max " << max * 1e6 << " um; left out near jumps "
            << a.wheels[0].excluded_near_jumps << " of " << a.wheels[0].points << "\n";
  EXPECT_LE(z_rms(a), 0.5e-6);
  EXPECT_LE(max, 5e-6);
  EXPECT_LT(a.wheels[0].excluded_near_jumps, a.wheels[0].points / 4);
  EXPECT_GT(a.wheels[0].jumps, 0);  // the box holds jumps of the tread point (y ~ 0.5 and ~5 mm)
  // The contact angle and rolling radius, which the creep forces need, follow as well.
  EXPECT_LE(a.wheels[0].continuous[kFieldContactAngle].rms_error, 3e-3);
  EXPECT_LE(a.wheels[0].continuous[kFieldRollingRadius].rms_error, 50e-6);
}

// Mirror symmetry: the right wheel at (y, roll, yaw) is the left wheel at (-y, -roll, -yaw)
// mirrored in y. The two wheels are sampled and fitted independently, so this checks the whole
// chain: equal z, s and angles, opposite lateral positions and normals, to rounding of the two
// fits: z to 1e-12 m, positions to 1e-11 m, and the slope dz/dy with the angle and normal that
// follow from it to 5e-9 (z's 1e-12 m over the fit's shortest knot interval, about 0.2 mm;
// measured 1.1e-9).
TEST(SplineGeometry, WheelsAreMirrorImages) {
  const SplineContactGeometry& m = *quick_spline_fit().model;
  for (double y : {-0.005, -0.0021, 0.0, 0.0013, 0.0047}) {
    for (double roll : {-0.0008, 0.0, 0.0005}) {
      for (double yaw : {-0.004, 0.0, 0.0031}) {
        WheelsetPose p;
        p.y = y, p.roll = roll, p.yaw = yaw, p.z = 0.46;
        WheelsetPose q = p;
        q.y = -y, q.roll = -roll, q.yaw = -yaw;
        SplineEvaluation l, r;
        m.evaluate(WheelSide::kLeft, p, SplineDerivatives::kGradient, l);
        m.evaluate(WheelSide::kRight, q, SplineDerivatives::kGradient, r);
        EXPECT_NEAR(l.value[kFieldZ], r.value[kFieldZ], 1e-12);
        EXPECT_NEAR(l.value[kFieldSWheel], r.value[kFieldSWheel], 1e-11);
        EXPECT_NEAR(l.value[kFieldContactAngle], r.value[kFieldContactAngle], 5e-9);
        EXPECT_NEAR(l.value[kFieldWheelY], -r.value[kFieldWheelY], 1e-11);
        EXPECT_NEAR(l.value[kFieldNormalY], -r.value[kFieldNormalY], 5e-9);
        EXPECT_NEAR(l.z_gradient[0], -r.z_gradient[0], 5e-9);
      }
    }
  }
}

// Distance in y from (y, roll, yaw) to the nearest jump of the left wheel's exact tread point,
// from a 10 um scan of +-2 mm around y.
double distance_to_jump(const WheelsetGeometry& g, double s_split, WheelsetPose p) {
  const double y0 = p.y;
  double best = 1.0, last_s = NAN, last_y = NAN;
  for (double y = y0 - 0.002; y <= y0 + 0.002; y += 1e-5) {
    p.y = y;
    const WheelSample s = sample_wheel(g, WheelSide::kLeft, p, s_split, 1e-3, 0.01, {});
    if (!std::isnan(last_s) && std::abs(s.tread.s - last_s) > 5e-4)
      best = std::min(best, std::abs(0.5 * (y + last_y) - y0));
    last_s = s.tread.s;
    last_y = y;
  }
  return best;
}

// The fitted z is C2 and its gradient is what a rigid-contact constraint uses: against central
// differences (h = 1 um) of the exact vertical displacement, at poses at least 1 mm from any jump.
// The exact z has slopes of up to ~0.12 (dz/dy = tan of the contact angle) and ~0.75 m/rad
// (dz/droll, the lateral lever of the contact point). The fit's z error (up to 3 um) changes sign
// over about a knot interval (~1 mm in y), so the gradient error in y can reach ~3 um / 0.8 mm =
// 4e-3 (measured 2.4e-3); roll and yaw span 2 mrad and 10 mrad with two intervals, over which the
// error hardly varies (measured 3.5e-4 and 3e-6 m/rad).
TEST(SplineGeometry, VerticalDisplacementGradientMatchesTheExactGeometry) {
  const SplineContactGeometry& m = *default_spline_fit().model;
  const WheelsetGeometry& g = *s1002_uic60_geometry();
  double worst[3] = {0, 0, 0};
  int checked = 0;
  for (double y : {-0.0045, -0.0025, 0.0025, 0.0035}) {
    for (double roll : {-0.0005, 0.0003}) {
      for (double yaw : {-0.002, 0.0015}) {
        WheelsetPose p;
        p.y = y, p.roll = roll, p.yaw = yaw, p.z = 0.46;
        if (distance_to_jump(g, m.s_split(), p) < 1e-3) continue;
        SplineEvaluation e;
        m.evaluate(WheelSide::kLeft, p, SplineDerivatives::kHessian, e);
        const double h = 1e-6;
        for (int k = 0; k < 3; ++k) {
          WheelsetPose a = p, b = p;
          double* pa = k == 0 ? &a.y : k == 1 ? &a.roll : &a.yaw;
          double* pb = k == 0 ? &b.y : k == 1 ? &b.roll : &b.yaw;
          *pa += h, *pb -= h;
          const double za = sample_wheel(g, WheelSide::kLeft, a, m.s_split(), 1e-3, 0.01, {}).fields[kFieldZ];
          const double zb = sample_wheel(g, WheelSide::kLeft, b, m.s_split(), 1e-3, 0.01, {}).fields[kFieldZ];
          worst[k] = std::max(worst[k], std::abs(e.z_gradient[static_cast<size_t>(k)] - (za - zb) / (2 * h)));
        }
        ++checked;
      }
    }
  }
  std::cout << "gradient errors (y, roll, yaw): " << worst[0] << ", " << worst[1] << ", " << worst[2] << " over "
            << checked << " poses\n";
  EXPECT_GE(checked, 8);
  EXPECT_LT(worst[0], 4e-3);   // [m/m]
  EXPECT_LT(worst[1], 1e-3);   // [m/rad]: 0.13 % of the lever arm 0.75 m
  EXPECT_LT(worst[2], 1e-4);   // [m/rad]
}

// The query's reduced evaluation (SplineModel: the 22 query fields, derivatives of z only) gives
// bit for bit what the full one gives for those, NaN for what it leaves out, and a derivative
// field count other than 1 or 2 is refused: the savings of the contact query change no number.
TEST(SplineGeometry, QueryEvaluationIsTheFullOneRestricted) {
  const SplineContactGeometry& m = *quick_spline_fit().model;
  WheelsetPose p;
  p.y = 0.0031, p.roll = -0.0004, p.yaw = 0.0012, p.z = 0.46;
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    if (side == WheelSide::kRight) p.y = -p.y;
    SplineEvaluation full, query;
    m.evaluate(side, p, SplineDerivatives::kHessian, full);
    m.evaluate(side, p, SplineDerivatives::kHessian, query, kSplineQueryFieldCount, 1);
    for (int j = 0; j < kSplineFieldCount; ++j) {
      if (j < kSplineQueryFieldCount) {
        EXPECT_EQ(query.value[static_cast<size_t>(j)], full.value[static_cast<size_t>(j)]) << kSplineFields[j].name;
      } else {
        EXPECT_TRUE(std::isnan(query.value[static_cast<size_t>(j)])) << kSplineFields[j].name;
        EXPECT_TRUE(std::isfinite(full.value[static_cast<size_t>(j)])) << kSplineFields[j].name;
      }
    }
    EXPECT_EQ(query.z_gradient, full.z_gradient);
    EXPECT_EQ(query.z_hessian, full.z_hessian);
    for (double v : query.clearance_gradient) EXPECT_TRUE(std::isnan(v));
    for (double v : full.clearance_gradient) EXPECT_TRUE(std::isfinite(v));
  }
  SplineEvaluation e;
  EXPECT_THROW(m.evaluate(WheelSide::kLeft, p, SplineDerivatives::kHessian, e, kSplineFieldCount, 3),
               std::invalid_argument);
  EXPECT_THROW(m.evaluate(WheelSide::kLeft, p, SplineDerivatives::kHessian, e, kSplineFieldCount, 0),
               std::invalid_argument);
}

// Fitted over a box that reaches into flange contact (y within +-12 mm, roll within +-30 mrad:
// where a vehicle's leading wheelsets run in a curve), the fit of the lateral curvature, which
// jumps where the flange starts to touch, overshoots below zero between its samples. Every patch
// the model gives is still a Hertz ellipse (A, B > 0, k' in (0, 1], K, E, m, n > 0): there the
// shape is the exact one of the fitted curvatures with B floored as the exact models floor it,
// and it says so (floored). A scan of the left wheel every 0.1 mm in y at three rolls and two yaws.
TEST(SplineGeometry, EveryPatchOfABoxOverFlangeContactIsAHertzEllipse) {
  SplineFitOptions o = quick_spline_options();
  o.y_min = -0.012;
  o.y_max = 0.012;
  o.roll_max = 0.03;
  o.yaw_max = 0.01;
  o.intervals[0] = 20;
  const SplineFit fit = fit_spline_geometry(*s1002_uic60_geometry(), o);
  const SplineContactGeometry& m = *fit.model;
  long scanned = 0, overshooting = 0;
  for (int i = -120; i <= 120; ++i)
    for (double roll : {-0.02, 0.0, 0.02})
      for (double yaw : {0.0, 0.005}) {
        WheelsetPose p;
        p.y = 1e-4 * i, p.roll = roll, p.yaw = yaw, p.z = 0.46;
        SplineEvaluation e;
        m.evaluate(WheelSide::kLeft, p, SplineDerivatives::kValue, e);
        if (!(e.value[kFieldHertzB] > 0.0)) ++overshooting;
        const HertzShape s = m.patch_shape(e).shape;
        EXPECT_TRUE(s.A > 0.0 && s.B > 0.0 && s.minor_over_major > 0.0 && s.minor_over_major <= 1.0 && s.K > 0.0 &&
                    s.E > 0.0 && s.m > 0.0 && s.n > 0.0)
            << "y = " << p.y << ", roll = " << roll << ", yaw = " << yaw << ": A = " << s.A << ", B = " << s.B;
        ++scanned;
      }
  EXPECT_GT(overshooting, 0) << "the scan should reach the overshoot this test is about";
  std::cout << "[ measured ] " << overshooting << " of " << scanned << " configurations with a fitted B <= 0\n";
}

// The jumps of the tread contact point are located automatically: on the line roll = yaw = 0 the
// bisection finds every jump that a dense 5 um scan of the exact common point sees, within 5 um,
// and nothing else. (S1002/UIC60: one near y = 0.2 mm, one at ~5.2 mm for the left wheel.)
TEST(SplineGeometry, JumpsAreFoundWhereTheExactCommonPointJumps) {
  const WheelsetGeometry& g = *s1002_uic60_geometry();
  const SplineFitOptions options;
  const double s_split = flange_split(g.wheel_profile(), options.flange_angle);
  const WheelSampleGrid grid = sample_wheel_grid(g, WheelSide::kLeft, sample_values(-0.006, 0.006, 121), {0.0}, {0.0},
                                                 options, s_split, 1);
  std::vector<double> dense;
  WheelsetPose p;
  p.z = 0.46;
  double last_s = NAN;
  for (int i = 0; i <= 2400; ++i) {
    p.y = -0.006 + 5e-6 * i;
    const double s = sample_wheel(g, WheelSide::kLeft, p, s_split, 1e-3, 0.01, {}).tread.s;
    if (!std::isnan(last_s) && std::abs(s - last_s) > 5e-4) dense.push_back(p.y - 2.5e-6);
    last_s = s;
  }
  const auto& found = grid.line_jumps[0];
  ASSERT_EQ(found.size(), dense.size());
  ASSERT_EQ(found.size(), 2u);
  for (size_t i = 0; i < dense.size(); ++i) EXPECT_NEAR(found[i].y, dense[i], 5e-6);
  EXPECT_NEAR(found[1].y, 0.0052, 2e-4);
  EXPECT_GT(found[1].s_before - found[1].s_after, 0.01);  // tread (-17.7 mm) to flange root (-28.6 mm)
}

// The weights do their job in the paper's form (one fit across the jumps, transition = 0): the
// same fit without down-weighting the jumps (jump_weight = 1) is pulled towards the kinks and is
// worse in the continuous region, by more than a third.
TEST(SplineGeometry, WeightsAtTheJumpsImproveTheContinuousRegion) {
  const WheelsetGeometry& g = *s1002_uic60_geometry();
  SplineFitOptions weighted = quick_spline_options();
  weighted.transition = 0.0;
  SplineFitOptions unweighted = weighted;
  unweighted.jump_weight = 1.0;
  const SplineFit plain = fit_spline_geometry(g, unweighted);
  const double weighted_rms = z_rms(validate_spline_geometry(g, *fit_spline_geometry(g, weighted).model, weighted));
  const double plain_rms = z_rms(validate_spline_geometry(g, *plain.model, unweighted));
  std::cout << "z rms: weighted " << weighted_rms * 1e6 << " um, unweighted " << plain_rms * 1e6 << " um\n";
  EXPECT_LT(weighted_rms, plain_rms / 1.5);
}

// The paper's form (one fit across the jumps) converges as knots are added: uniform 5, 10, 20
// intervals in y, each halving reduces the continuous-region RMS of z (the kinks limit the
// order, so no rate is asserted). The branch fits have no kinks to smooth: with 5 intervals per
// branch z is within 0.1 um rms already (measured 0.034 um; 10 and 20: 0.031 um, the floor
// of this coarse sample grid), and more knots do not make it worse.
TEST(SplineGeometry, ConvergesAsKnotsAreAdded) {
  const WheelsetGeometry& g = *s1002_uic60_geometry();
  double last = 1.0;
  for (int n : {5, 10, 20}) {
    SplineFitOptions o = quick_spline_options();
    o.transition = 0.0;
    o.placement = KnotPlacement::kUniform;
    o.intervals[0] = n;
    const double rms = z_rms(validate_spline_geometry(g, *fit_spline_geometry(g, o).model, o));
    std::cout << n << " intervals, one fit: z rms " << rms * 1e6 << " um\n";
    EXPECT_LT(rms, last) << n;
    last = rms;
  }
  for (int n : {5, 10, 20}) {
    SplineFitOptions o = quick_spline_options();
    o.intervals[0] = n;
    const double rms = z_rms(validate_spline_geometry(g, *fit_spline_geometry(g, o).model, o));
    std::cout << n << " intervals per branch: z rms " << rms * 1e6 << " um\n";
    EXPECT_LT(rms, 1e-7) << n;
    EXPECT_LT(rms, last * 1.05) << n;
    last = std::min(last, rms);
  }
}

}  // namespace
}  // namespace wrc
