// The spline model's branches (S1002/UIC60): one fit per stretch of the tread contact point
// between two jumps, the jump surfaces through the jumps found on the sample lines, and the C2
// blend within `transition` of a jump, whose value, gradient and Hessian are those of one smooth
// function (against central differences), with the creep frame from the gradient of z.
#include <gtest/gtest.h>

#include <cmath>

#include "spline_test_model.hpp"

namespace wrc {
namespace {

// Both wheels of the default model have three branches (tread, tread towards the flange root,
// flange root) and two jump surfaces that pass through every jump found on the sample lines
// within 1 um (measured 0.05 um, the bisection stops at 0.1 um; the jumps move by about -0.5 mm
// per mrad of roll, smoothly).
TEST(SplineBranches, JumpSurfacesFollowTheSampledJumps) {
  const SplineFit& fit = test::default_spline_fit();
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const SplineWheel& w = fit.model->wheel(side);
    ASSERT_EQ(w.branches.size(), 3u) << side_name(side);
    ASSERT_EQ(w.jumps.size(), 2u);
    double worst = 0;
    for (const TreadJump& j : fit.wheels[static_cast<size_t>(side)].jumps) {
      double nearest = 1.0;
      for (const JumpSurface& surface : w.jumps) nearest = std::min(nearest, std::abs(surface.at(j.roll, j.yaw) - j.y));
      worst = std::max(worst, nearest);
    }
    std::printf("[ measured ] %s wheel: jump surfaces within %.3g um of the sampled jumps\n", side_name(side),
                worst * 1e6);
    EXPECT_LT(worst, 1e-6);
  }
}

// Within the transition of the left wheel's jump near y = 5.1 mm the blended z's gradient and
// Hessian match central differences of the blended z and gradient (steps 1e-7 m, 1e-7 rad: the
// blend's third derivatives are ~1e5 times larger than the branches', so a relative 1e-4 of the
// largest entry), the flange clearance is blended the same way, and the contact angle and the
// normal are those of dz/dy: tan(angle) = dz/dy (left wheel), n = (0, -g, 1) / sqrt(1 + g^2).
TEST(SplineBranches, BlendHasItsOwnDerivativesAndTheFrameOfGradZ) {
  const SplineContactGeometry& model = *test::default_spline_fit().model;
  const SplineWheel& w = model.wheel(WheelSide::kLeft);
  const double roll = 3e-4, yaw = 1e-3;
  const double jump = w.jumps[1].at(roll, yaw);
  ASSERT_GT(jump, 0.004);
  auto eval = [&](double y, double r, double p) {
    WheelsetPose pose;
    pose.y = y, pose.roll = r, pose.yaw = p, pose.z = 0.46;
    SplineEvaluation e;
    model.evaluate(WheelSide::kLeft, pose, SplineDerivatives::kHessian, e);
    return e;
  };
  const double h = 1e-7;
  for (double t : {-0.9, -0.5, 0.0, 0.3, 0.8}) {
    const double y = jump + t * model.transition();
    const SplineEvaluation e = eval(y, roll, yaw);
    const SplineEvaluation f[3][2] = {{eval(y + h, roll, yaw), eval(y - h, roll, yaw)},
                                      {eval(y, roll + h, yaw), eval(y, roll - h, yaw)},
                                      {eval(y, roll, yaw + h), eval(y, roll, yaw - h)}};
    double scale = 0;
    for (double v : e.z_hessian) scale = std::max(scale, std::abs(v));
    for (int k = 0; k < 3; ++k) {
      const double fd = (f[k][0].value[kFieldZ] - f[k][1].value[kFieldZ]) / (2 * h);
      EXPECT_NEAR(e.z_gradient[static_cast<size_t>(k)], fd, 1e-6 + 1e-5 * std::abs(fd)) << "t " << t << " k " << k;
      const double fc = (f[k][0].value[kFieldFlangeClearance] - f[k][1].value[kFieldFlangeClearance]) / (2 * h);
      EXPECT_NEAR(e.clearance_gradient[static_cast<size_t>(k)], fc, 1e-6 + 1e-5 * std::abs(fc)) << "t " << t;
    }
    // Hessian slots (y,y), (y,roll), (y,yaw), (roll,roll), (roll,yaw), (yaw,yaw) from the gradient.
    const int row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};
    for (int q = 0; q < 6; ++q) {
      const size_t k = static_cast<size_t>(row[q]);
      const int l = col[q];
      const double fd = (f[l][0].z_gradient[k] - f[l][1].z_gradient[k]) / (2 * h);
      EXPECT_NEAR(e.z_hessian[static_cast<size_t>(q)], fd, 1e-4 * scale) << "t " << t << " slot " << q;
    }
    const double g = e.z_gradient[0];
    EXPECT_NEAR(std::tan(e.value[kFieldContactAngle]), g, 1e-14);
    EXPECT_NEAR(e.value[kFieldNormalY], -g / std::sqrt(1 + g * g), 1e-15);
    EXPECT_NEAR(e.value[kFieldNormalZ], 1 / std::sqrt(1 + g * g), 1e-15);
  }
}

// Outside every transition the model is its branch's fit alone: at the edges of the transition
// the blend weight and its first two derivatives vanish, so the values just inside and outside
// the edge agree to the branches' own variation (C2 join: within 1e-9 m of z over 2e-9 m of y).
TEST(SplineBranches, TransitionJoinsTheBranchesSmoothly) {
  const SplineContactGeometry& model = *test::default_spline_fit().model;
  const double jump = model.wheel(WheelSide::kLeft).jumps[0].at(0.0, 0.0);
  for (double edge : {jump - model.transition(), jump + model.transition()}) {
    WheelsetPose in, out;
    in.z = out.z = 0.46;
    in.y = edge + (edge < jump ? 1e-9 : -1e-9);
    out.y = edge + (edge < jump ? -1e-9 : 1e-9);
    SplineEvaluation a, b;
    model.evaluate(WheelSide::kLeft, in, SplineDerivatives::kHessian, a);
    model.evaluate(WheelSide::kLeft, out, SplineDerivatives::kHessian, b);
    EXPECT_NEAR(a.value[kFieldZ], b.value[kFieldZ], 1e-9);
    EXPECT_NEAR(a.value[kFieldSWheel], b.value[kFieldSWheel], 1e-6);
    EXPECT_NEAR(a.z_gradient[0], b.z_gradient[0], 1e-6);
    EXPECT_NEAR(a.z_hessian[0], b.z_hessian[0], 1e-2 * std::max(1.0, std::abs(b.z_hessian[0])));
  }
}

}  // namespace
}  // namespace wrc
