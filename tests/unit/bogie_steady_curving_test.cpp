// SPDX-License-Identifier: Apache-2.0
// The linear steady-curving theory of a two-axle bogie (core/vehicle/bogie_steady_curving.hpp,
// derived in docs/bogie-curving.md): its exact limits (no primary suspension: the pure rolling
// line; a rigid bogie and a yaw-rigid one approached at the rate 1/k; a lateral force on straight
// track carried by lateral creep), the mirror symmetry of the curve, linearity in the curvature and
// the loads, every body's force and moment balance recomputed here from the returned displacements
// (creepages from the contact points' velocities, springs from their attachment points), the
// classical angle of attack a/R of a stiff bogie, and the refusal of bad parameters.
//
// The bogie is the Cooperrider car's (docs/vehicle.md, "Parameter sets", values of DTU's DYTSI):
// frame 2918.9 kg, wheelset 1022 kg, half wheelbase 1.074 m, rolling radius 0.425 m, contact
// half distance 0.75 m; primary springs per axle box 3.646e6 N/m longitudinal at +-0.62 m and
// 1.823e6 N/m lateral; secondary springs per side 1.823e5 N/m lateral and 9.0335e5 N/m
// longitudinal at +-0.68 m (so k_sy = 3.646e5 N/m, k_spsi = 2 x 9.0335e5 x 0.68^2 N m/rad), tied
// to a body that follows the track (parameters/vehicles/cooperrider-bogie.json). Its contact,
// S1002 on UIC60 1:40 at the static wheel load 66.6 kN, from wrc's own geometry and contact
// (core/dynamics/wickens_from_model.hpp, docs/bogie-curving.md "Numbers"): f11 = 14.01 MN,
// f22 = 11.28 MN, f23 = 23.4 kN m per wheel; conicity 0.15, the secant conicity
// (r_left - r_right) / (2 y) at 3 to 5 mm, where the wheelsets run in a 600 m curve.
#include "core/vehicle/bogie_steady_curving.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wrc {
namespace {

constexpr double kG = 9.81;

BogieCurvingParameters cooperrider() {
  BogieCurvingParameters p;
  p.frame_mass = 2918.9;
  p.wheelset_mass = 1022.0;
  p.semi_wheelbase = 1.074;
  p.conicity = 0.15;
  p.rolling_radius = 0.425;
  p.contact_half_distance = 0.75;
  p.f11 = 14.01e6;
  p.f22 = 11.28e6;
  p.primary_longitudinal_stiffness = 3.646e6;
  p.primary_lateral_stiffness = 1.823e6;
  p.primary_semi_spacing = 0.62;
  p.secondary_lateral_stiffness = 2.0 * 1.823e5;
  p.secondary_yaw_stiffness = 2.0 * 9.0335e5 * 0.68 * 0.68;
  return p;
}

// Every optional term switched on, with values of their real size: a cant deficiency of 0.05 rad
// on every body and half the car body; f23 and f33 of the S1002 patch (23.4 kN m, 363 N m^2); a
// contact-angle slope of 5 rad/m; the gravitational stiffness of the cone, 18.8 kN/m; a car body
// on pivots at +-7.5 m seen from the front bogie (yaw -7.5 kappa), shifted 2 mm.
BogieCurvingParameters everything(double radius) {
  BogieCurvingParameters p = cooperrider();
  p.curvature = 1.0 / radius;
  p.lateral_acceleration = lateral_acceleration_of_cant_deficiency(0.05, p.curvature);
  p.frame_lateral_force = -0.5 * 44388.0 * kG * 0.05;  // half the car body's load: one bogie's share
  p.wheelset_lateral_force = 1500.0;
  p.gravitational_lateral_stiffness = 1.876e4;
  p.f23 = 2.338e4;
  p.f33 = 362.8;
  p.contact_angle_slope = 5.0;
  p.body_lateral_offset = 2e-3;
  p.body_yaw = -7.5 * p.curvature;
  return p;
}

// q = (y_f, psi_f, y_1, psi_1, y_2, psi_2)
std::array<double, 6> q_of(const BogieCurvingResult& r) {
  return {r.frame_lateral, r.frame_yaw, r.wheelsets[0].lateral, r.wheelsets[0].yaw, r.wheelsets[1].lateral,
          r.wheelsets[1].yaw};
}

// The largest difference of two results, lateral ones over y_scale [m] and angles over psi_scale [rad].
double scaled_difference(const std::array<double, 6>& a, const std::array<double, 6>& b, double y_scale,
                         double psi_scale) {
  double d = 0.0;
  for (int k = 0; k < 6; ++k) d = std::max(d, std::abs(a[k] - b[k]) / (k % 2 == 0 ? y_scale : psi_scale));
  return d;
}

// The rigid bogie (docs/bogie-curving.md, limit (b)): both wheelsets fixed in the frame, the frame's
// y_f and psi_f from the whole bogie's lateral force and yaw moment balance (optional spin terms off).
std::array<double, 6> rigid_bogie(const BogieCurvingParameters& p) {
  const double kappa = p.curvature, a = p.semi_wheelbase, b0 = p.contact_half_distance, r0 = p.rolling_radius;
  const double kg = p.gravitational_lateral_stiffness;
  const double total_force = (p.frame_mass + 2.0 * p.wheelset_mass) * p.lateral_acceleration + p.frame_lateral_force +
                             2.0 * p.wheelset_lateral_force;
  const double c = 2.0 * p.f11 * b0 * p.conicity / r0;
  // [2 k_g + k_sy, -4 f22; 2 c, 2 k_g a^2 + k_spsi] (y_f, psi_f) = (g1, g2)
  const double m11 = 2.0 * kg + p.secondary_lateral_stiffness, m12 = -4.0 * p.f22;
  const double m21 = 2.0 * c, m22 = 2.0 * kg * a * a + p.secondary_yaw_stiffness;
  const double g1 = total_force + kg * a * a * kappa + p.secondary_lateral_stiffness * p.body_lateral_offset;
  const double g2 = -4.0 * p.f11 * b0 * b0 * kappa + c * a * a * kappa - 4.0 * p.f22 * a * a * kappa +
                    p.secondary_yaw_stiffness * p.body_yaw;
  const double det = m11 * m22 - m12 * m21;
  const double yf = (g1 * m22 - m12 * g2) / det;
  const double psif = (m11 * g2 - m21 * g1) / det;
  return {yf, psif, yf + a * psif - 0.5 * a * a * kappa, psif - a * kappa, yf - a * psif - 0.5 * a * a * kappa,
          psif + a * kappa};
}

// (a) No primary suspension: each wheelset rolls without longitudinal creep, on the pure rolling
// line y = -r0 b0 / (lambda R) (to the right, towards the outer rail, in a curve to the left) with
// no yaw and so no lateral creep; the frame sits where the secondary puts it. Exact to rounding.
TEST(BogieSteadyCurving, WithoutPrimarySuspensionEachWheelsetRollsOnThePureRollingLine) {
  BogieCurvingParameters p = cooperrider();
  p.curvature = 1.0 / 600.0;
  p.primary_longitudinal_stiffness = 0.0;
  p.primary_lateral_stiffness = 0.0;
  p.body_lateral_offset = 1e-3;
  p.body_yaw = -0.01;
  const BogieCurvingResult r = bogie_steady_curving(p);
  const double rolling_line = -0.425 * 0.75 / (0.15 * 600.0);  // -3.542 mm
  EXPECT_NEAR(r.pure_rolling_lateral, rolling_line, 1e-12 * std::abs(rolling_line));
  for (const WheelsetCurvingState& w : r.wheelsets) {
    EXPECT_NEAR(w.lateral, rolling_line, 1e-12 * std::abs(rolling_line));
    EXPECT_NEAR(w.yaw, 0.0, 1e-12 * 1.074 / 600.0);
    EXPECT_NEAR(w.angle_of_attack(), 0.0, 1e-12 * 1.074 / 600.0);
    EXPECT_NEAR(w.longitudinal_creep_force_left, 0.0, 1e-12 * 14.01e6 * 0.75 / 600.0);
  }
  EXPECT_NEAR(r.frame_lateral, 1e-3, 1e-15);
  EXPECT_NEAR(r.frame_yaw, -0.01, 1e-15);

  // (d) Without longitudinal springs alone the wheelsets still lie on the rolling line exactly,
  // whatever the lateral springs and loads: their yaw balance holds only the creep moment.
  p = everything(600.0);
  p.f23 = p.f33 = 0.0;
  p.primary_longitudinal_stiffness = 0.0;
  const BogieCurvingResult d = bogie_steady_curving(p);
  for (const WheelsetCurvingState& w : d.wheelsets) EXPECT_NEAR(w.lateral, rolling_line, 1e-12 * std::abs(rolling_line));
}

// (b) As the primary stiffnesses grow together (k_x = k_y = s times Cooperrider's), the bogie tends
// to the rigid one: both wheelsets at one offset, angles of attack -+a/R plus the frame's yaw, the
// frame from the whole bogie's balance (here with the secondary, a cant deficiency and the
// gravitational stiffness). The deviation is a regular perturbation in 1/s: each tenfold s divides
// it by 10 (measured 9.94, 9.997, 10.000 from s = 1e2 on), and at s = 1e5 it is 1e-4 of the
// scales (y0 and a/R).
TEST(BogieSteadyCurving, StiffPrimaryApproachesTheRigidBogieAtRateOneOverStiffness) {
  BogieCurvingParameters p = everything(600.0);
  p.f23 = p.f33 = p.contact_angle_slope = 0.0;
  const std::array<double, 6> rigid = rigid_bogie(p);
  const double y_scale = std::abs(-0.425 * 0.75 / (0.15 * 600.0)), psi_scale = 1.074 / 600.0;
  std::vector<double> errors;
  for (double s : {1e2, 1e3, 1e4, 1e5}) {
    BogieCurvingParameters stiff = p;
    stiff.primary_longitudinal_stiffness *= s;
    stiff.primary_lateral_stiffness *= s;
    errors.push_back(scaled_difference(q_of(bogie_steady_curving(stiff)), rigid, y_scale, psi_scale));
  }
  EXPECT_LT(errors.back(), 1e-3);
  for (std::size_t k = 1; k + 1 < errors.size(); ++k)
    EXPECT_NEAR(errors[k] / errors[k + 1], 10.0, 0.2) << "s = 1e" << k + 2;

  // The classical form (no secondary, no load, no gravitational stiffness): both wheelsets at
  // y0 (1 + f22 a^2 / (f11 b0^2)), psi_1 = -a/R, psi_2 = +a/R.
  BogieCurvingParameters classic = cooperrider();
  classic.curvature = 1.0 / 600.0;
  classic.secondary_lateral_stiffness = classic.secondary_yaw_stiffness = 0.0;
  classic.primary_longitudinal_stiffness *= 1e6;
  classic.primary_lateral_stiffness *= 1e6;
  const BogieCurvingResult r = bogie_steady_curving(classic);
  const double y = -0.425 * 0.75 / (0.15 * 600.0) * (1.0 + 11.28e6 * 1.074 * 1.074 / (14.01e6 * 0.75 * 0.75));
  for (const WheelsetCurvingState& w : r.wheelsets) EXPECT_NEAR(w.lateral, y, 1e-5 * std::abs(y));  // -9.38 mm
  EXPECT_NEAR(r.wheelsets[0].yaw, -psi_scale, 1e-5 * psi_scale);
  EXPECT_NEAR(r.wheelsets[1].yaw, psi_scale, 1e-5 * psi_scale);
}

// (d) Yaw-rigid primary with lateral springs (k_x grows alone, no secondary, no load): the angles of
// attack tend to -+a/R, the wheelsets to y0 (1 + f22 a^2 / (f11 b0^2)) -+ f22 a / (k_y R): each
// wheelset's lateral creep force 2 f22 psi_i deflects its two lateral springs 2 k_y. Rate 1/k_x
// (error ratios per tenfold k_x measured 8.84, 9.87, 9.99; 3e-4 of the scales at 1e5 k_x).
TEST(BogieSteadyCurving, YawRigidPrimaryApproachesItsClosedFormAtRateOneOverStiffness) {
  BogieCurvingParameters p = cooperrider();
  p.curvature = 1.0 / 1000.0;
  p.secondary_lateral_stiffness = 0.0;  // the frame's lateral balance then holds psi_1 + psi_2 = 0
  const double a = 1.074, kappa = 1e-3;
  const double amplified = -0.425 * 0.75 / 0.15 * kappa * (1.0 + 11.28e6 * a * a / (14.01e6 * 0.75 * 0.75));
  const double split = 11.28e6 * a * kappa / 1.823e6;
  const std::array<double, 6> limit = {amplified + 0.5 * a * a * kappa, 0.0, amplified - split, -a * kappa,
                                       amplified + split, a * kappa};
  std::vector<double> errors;
  for (double s : {1e2, 1e3, 1e4, 1e5}) {
    BogieCurvingParameters stiff = p;
    stiff.primary_longitudinal_stiffness *= s;
    errors.push_back(scaled_difference(q_of(bogie_steady_curving(stiff)), limit, std::abs(amplified), a * kappa));
  }
  EXPECT_LT(errors.back(), 1e-3);
  for (std::size_t k = 1; k + 1 < errors.size(); ++k)
    EXPECT_NEAR(errors[k] / errors[k + 1], 10.0, 0.2) << "s = 1e" << k + 2;
}

// (c) Straight track, a lateral load only (cant deficiency, no secondary, no gravitational
// stiffness): lateral creep carries the whole load, 2 f22 (psi_1 + psi_2) = -F, and the creep
// moments balance, -(2 f11 b0 lambda / r0)(y_1 + y_2) + 2 f22 a (psi_1 - psi_2) = 0; with the
// primary springs the split psi_1 - psi_2 has the closed form of docs/bogie-curving.md. Exact.
TEST(BogieSteadyCurving, OnStraightTrackALateralLoadIsCarriedByLateralCreep) {
  BogieCurvingParameters p = cooperrider();
  p.secondary_lateral_stiffness = p.secondary_yaw_stiffness = 0.0;
  p.lateral_acceleration = -0.6;
  p.frame_lateral_force = -2000.0;
  p.wheelset_lateral_force = 300.0;
  const BogieCurvingResult r = bogie_steady_curving(p);
  const double a = 1.074;
  const double fw = 1022.0 * -0.6 + 300.0, ff = 2918.9 * -0.6 - 2000.0, total = 2.0 * fw + ff;
  const double creep_lateral = 2.0 * 11.28e6, creep_yaw = 2.0 * 14.01e6 * 0.75 * 0.15 / 0.425;
  const double k = 2.0 * 3.646e6 * 0.62 * 0.62, c = 2.0 * 1.823e6;
  const double sum_psi = -total / creep_lateral;
  const double diff_psi = -(creep_yaw * a / k) * sum_psi /
                          (1.0 + creep_yaw * creep_lateral * (a * a / (k * k) + 1.0 / (k * c)));
  const double sum_y = a * creep_lateral * diff_psi / creep_yaw;
  const double diff_y = -k * diff_psi / creep_yaw;
  const double psi_scale = std::abs(sum_psi), y_scale = std::abs(sum_y) + std::abs(diff_y) + std::abs(ff / c);
  EXPECT_NEAR(r.wheelsets[0].yaw, 0.5 * (sum_psi + diff_psi), 1e-12 * psi_scale);
  EXPECT_NEAR(r.wheelsets[1].yaw, 0.5 * (sum_psi - diff_psi), 1e-12 * psi_scale);
  EXPECT_NEAR(r.wheelsets[0].lateral, 0.5 * (sum_y + diff_y), 1e-12 * y_scale);
  EXPECT_NEAR(r.wheelsets[1].lateral, 0.5 * (sum_y - diff_y), 1e-12 * y_scale);
  EXPECT_NEAR(r.frame_yaw, 0.5 * (sum_psi + a * creep_lateral * diff_psi / k), 1e-12 * psi_scale);
  EXPECT_NEAR(r.frame_lateral, 0.5 * (sum_y + ff / c), 1e-12 * y_scale);
  EXPECT_NEAR(r.wheelsets[0].lateral_creep_force + r.wheelsets[1].lateral_creep_force, -total, 1e-12 * std::abs(total));
  EXPECT_DOUBLE_EQ(r.pure_rolling_lateral, 0.0);
}

// Mirror image: the curve to the other side with every lateral load, offset and yaw negated
// negates every result (the track, the bogie and the contact are symmetric about x-z).
TEST(BogieSteadyCurving, MirroredCurveAndLoadsNegateEveryLateralResult) {
  const BogieCurvingParameters p = everything(800.0);
  BogieCurvingParameters m = p;
  m.curvature = -p.curvature;
  m.lateral_acceleration = -p.lateral_acceleration;
  m.frame_lateral_force = -p.frame_lateral_force;
  m.wheelset_lateral_force = -p.wheelset_lateral_force;
  m.body_lateral_offset = -p.body_lateral_offset;
  m.body_yaw = -p.body_yaw;
  const BogieCurvingResult r = bogie_steady_curving(p), s = bogie_steady_curving(m);
  const auto mirrored = [](double x, double y) { EXPECT_NEAR(x, -y, 1e-13 * std::abs(y) + 1e-300) << x << " " << y; };
  mirrored(r.frame_lateral, s.frame_lateral);
  mirrored(r.frame_yaw, s.frame_yaw);
  mirrored(r.secondary_lateral_force, s.secondary_lateral_force);
  mirrored(r.secondary_yaw_moment, s.secondary_yaw_moment);
  mirrored(r.pure_rolling_lateral, s.pure_rolling_lateral);
  for (int i = 0; i < 2; ++i) {
    const WheelsetCurvingState &w = r.wheelsets[i], &v = s.wheelsets[i];
    mirrored(w.lateral, v.lateral);
    mirrored(w.yaw, v.yaw);
    mirrored(w.lateral_creep_force, v.lateral_creep_force);
    mirrored(w.creep_yaw_moment, v.creep_yaw_moment);
    mirrored(w.primary_lateral_force, v.primary_lateral_force);
    mirrored(w.primary_yaw_moment, v.primary_yaw_moment);
    // The left wheel's longitudinal creepage becomes the right wheel's, the negative of the left one's.
    mirrored(w.longitudinal_creepage_left, v.longitudinal_creepage_left);
  }
}

// Each body's balance rebuilt here from the displacements the function returns, with every
// optional term on: creepages from the velocities of the contact points (the wheelset turning
// at V/R about the curve's centre and spinning at V/r0), Kalker's linear law, and the springs
// from their attachment points on both bodies (axle boxes at (x_i, +-b1)). Zero to rounding.
TEST(BogieSteadyCurving, EveryBodyIsInForceAndMomentBalance) {
  for (double radius : {600.0, -3000.0}) {
    const BogieCurvingParameters p = everything(radius);
    const BogieCurvingResult r = bogie_steady_curving(p);
    EXPECT_LT(r.relative_residual, 1e-12);
    const double V = 30.0, kappa = p.curvature, a = p.semi_wheelbase, r0 = p.rolling_radius, b0 = p.contact_half_distance;
    const double b1 = p.primary_semi_spacing;
    // Balances in frame-centre axes: [frame y, frame yaw, ws1 y, ws1 yaw, ws2 y, ws2 yaw] and each one's scale.
    std::array<double, 6> sum{}, scale{};
    const auto add = [&](int row, double term) {
      sum[row] += term;
      scale[row] = std::max(scale[row], std::abs(term));
    };
    for (int i = 0; i < 2; ++i) {
      const double x = i == 0 ? a : -a;
      const WheelsetCurvingState& w = r.wheelsets[i];
      // Contact points at +-b0 across the wheelset: forward speed V (1 - kappa (+-b0)) from the
      // turning at V kappa, minus the spin's V / r0 times the rolling radius r0 +- lambda y.
      double lateral = 0.0, moment = 0.0;
      for (double side : {1.0, -1.0}) {
        const double xi_x = (V * (1.0 - kappa * side * b0) - V / r0 * (r0 + side * p.conicity * w.lateral)) / V;
        const double xi_y = -w.yaw;  // moving along the local tangent, pointing psi off it
        // Spin: the turning V kappa about z and the spin V / r0 about the axle, on the normal tilted
        // by the contact angle relative to the axle, gamma0 +- eps y, towards the track centre
        // (any gamma0: its forces cancel between the wheels).
        const double gamma = 0.03 + side * p.contact_angle_slope * w.lateral;
        const double phi = kappa - side * gamma / r0;
        const double fx = -p.f11 * xi_x, fy = -p.f22 * xi_y - p.f23 * phi, mz = p.f23 * xi_y - p.f33 * phi;
        lateral += fy;
        moment += -side * b0 * fx + mz;
        if (side > 0) {
          EXPECT_NEAR(w.longitudinal_creepage_left, xi_x, 1e-14);  // xi_x: a difference of terms of size 1
          EXPECT_NEAR(w.longitudinal_creep_force_left, fx, 1e-9 * std::abs(fx) + 1e-9);
        }
      }
      EXPECT_NEAR(w.lateral_creep_force, lateral, 1e-9 * std::abs(lateral) + 1e-9);
      EXPECT_NEAR(w.creep_yaw_moment, moment, 1e-9 * std::abs(moment) + 1e-9);
      // The wheelset in frame-centre axes: centre at (x, y_i + kappa x^2 / 2), yaw psi_i + kappa x.
      const double centre_y = w.lateral + 0.5 * kappa * x * x, heading = w.yaw + kappa * x;
      double spring_y = 0.0, spring_moment = 0.0;
      for (double side : {1.0, -1.0}) {
        const double box_x = x - side * b1 * heading, box_y = centre_y + side * b1;
        const double frame_x = x - side * b1 * r.frame_yaw, frame_y = r.frame_lateral + x * r.frame_yaw + side * b1;
        const double fx = -p.primary_longitudinal_stiffness * (box_x - frame_x);
        const double fy = -p.primary_lateral_stiffness * (box_y - frame_y);
        spring_y += fy;
        spring_moment += -side * b1 * fx;  // about the wheelset's centre (lever (0, +-b1))
        add(0, -fy);
        add(1, x * -fy - side * b1 * -fx);  // on the frame at (x, +-b1)
      }
      EXPECT_NEAR(w.primary_lateral_force, spring_y, 1e-9 * std::abs(spring_y) + 1e-9);
      EXPECT_NEAR(w.primary_yaw_moment, spring_moment, 1e-9 * std::abs(spring_moment) + 1e-9);
      add(2 + 2 * i, lateral);
      add(2 + 2 * i, spring_y);
      add(2 + 2 * i, -p.gravitational_lateral_stiffness * w.lateral);
      add(2 + 2 * i, p.wheelset_mass * p.lateral_acceleration + p.wheelset_lateral_force);
      add(3 + 2 * i, moment);
      add(3 + 2 * i, spring_moment);
    }
    add(0, -p.secondary_lateral_stiffness * (r.frame_lateral - p.body_lateral_offset));
    add(0, p.frame_mass * p.lateral_acceleration + p.frame_lateral_force);
    add(1, -p.secondary_yaw_stiffness * (r.frame_yaw - p.body_yaw));
    for (int row = 0; row < 6; ++row) EXPECT_LT(std::abs(sum[row]), 1e-11 * scale[row]) << "R " << radius << " row " << row;
  }
}

// The theory is linear: twice the curvature gives twice every result, and a curve with a load is
// the sum of the curve alone and the load alone on straight track.
TEST(BogieSteadyCurving, ResultsAreLinearInTheCurvatureAndTheLoads) {
  BogieCurvingParameters p = everything(1200.0);
  p.body_yaw = 0.0;
  BogieCurvingParameters curve = p;
  curve.lateral_acceleration = curve.frame_lateral_force = curve.wheelset_lateral_force = curve.body_lateral_offset = 0.0;
  BogieCurvingParameters sharper = curve;
  sharper.curvature = 2.0 * curve.curvature;
  BogieCurvingParameters load = p;
  load.curvature = 0.0;
  const std::array<double, 6> once = q_of(bogie_steady_curving(curve)), twice = q_of(bogie_steady_curving(sharper));
  const std::array<double, 6> both = q_of(bogie_steady_curving(p)), alone = q_of(bogie_steady_curving(load));
  const double y_scale = 0.425 * 0.75 / (0.15 * 1200.0), psi_scale = 1.074 / 1200.0;
  std::array<double, 6> doubled{}, summed{};
  for (int k = 0; k < 6; ++k) {
    doubled[k] = 2.0 * once[k];
    summed[k] = once[k] + alone[k];
  }
  EXPECT_LT(scaled_difference(twice, doubled, y_scale, psi_scale), 1e-12);
  EXPECT_LT(scaled_difference(both, summed, y_scale, psi_scale), 1e-12);
}

// Issue 29: a stiff bogie's leading wheelset meets the rail at an angle of attack of order a/R,
// about 2 mrad for a = 1.25 m in a 600 m curve (a/R = 2.08 mrad; measured -2.17 and +2.00 mrad
// with primary springs 1000 times Cooperrider's: the frame's yaw, -0.10 mrad, from the secondary
// springs, adds to both). Cooperrider's own primary yaw stiffness (2 k_x b1^2 = 2.8 MN m/rad) is
// soft against the creep's 2 f11 b0^2 = 15.8 MN m: its wheelsets steer nearly radially (measured
// -0.062 mrad, 3 % of a/R).
TEST(BogieSteadyCurving, StiffBogieLeadingAngleOfAttackIsAboutSemiWheelbaseOverRadius) {
  BogieCurvingParameters p = cooperrider();
  p.curvature = 1.0 / 600.0;
  p.semi_wheelbase = 1.25;
  BogieCurvingParameters stiff = p;
  stiff.primary_longitudinal_stiffness *= 1e3;
  stiff.primary_lateral_stiffness *= 1e3;
  const double a_over_r = 1.25 / 600.0;
  const BogieCurvingResult r = bogie_steady_curving(stiff);
  EXPECT_LT(r.wheelsets[0].lateral, 0.0);  // in a curve to the left: towards the outer (right) rail
  EXPECT_NEAR(r.wheelsets[0].angle_of_attack(), -a_over_r, 0.1 * a_over_r);  // pointing to the outer rail
  EXPECT_NEAR(r.wheelsets[1].angle_of_attack(), a_over_r, 0.1 * a_over_r);
  EXPECT_NEAR(r.wheelsets[0].angle_of_attack() - r.wheelsets[1].angle_of_attack(), -2.0 * a_over_r, 1e-3 * a_over_r);
  const BogieCurvingResult soft = bogie_steady_curving(p);
  EXPECT_LT(std::abs(soft.wheelsets[0].angle_of_attack()), 0.05 * a_over_r);
}

TEST(BogieSteadyCurving, CantDeficiencyPushesOutOfTheCurve) {
  EXPECT_DOUBLE_EQ(lateral_acceleration_of_cant_deficiency(0.1, 1.0 / 500.0), -0.981);
  EXPECT_DOUBLE_EQ(lateral_acceleration_of_cant_deficiency(0.1, -1.0 / 500.0), 0.981);
  EXPECT_DOUBLE_EQ(lateral_acceleration_of_cant_deficiency(0.1, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(lateral_acceleration_of_cant_deficiency(-0.05, 1.0 / 500.0, 10.0), 0.5);  // cant excess
}

TEST(BogieSteadyCurving, ValidateRefusesBadValuesNamingThem) {
  using Change = std::function<void(BogieCurvingParameters&)>;
  const double nan = std::nan("");
  const std::vector<std::pair<Change, std::vector<const char*>>> cases = {
      {[&](BogieCurvingParameters& p) { p.curvature = nan; }, {"curvature", "nan", "[1/m]"}},
      {[](BogieCurvingParameters& p) { p.lateral_acceleration = INFINITY; }, {"lateral_acceleration", "inf"}},
      {[&](BogieCurvingParameters& p) { p.frame_lateral_force = nan; }, {"frame_lateral_force"}},
      {[&](BogieCurvingParameters& p) { p.wheelset_lateral_force = nan; }, {"wheelset_lateral_force"}},
      {[](BogieCurvingParameters& p) { p.frame_mass = 0.0; }, {"frame_mass", "= 0 [kg]", "> 0"}},
      {[](BogieCurvingParameters& p) { p.wheelset_mass = -1022.0; }, {"wheelset_mass", "-1022"}},
      {[](BogieCurvingParameters& p) { p.semi_wheelbase = 0.0; }, {"semi_wheelbase", "[m]"}},
      {[](BogieCurvingParameters& p) { p.conicity = 0.0; }, {"conicity", "= 0 [-]"}},
      {[](BogieCurvingParameters& p) { p.rolling_radius = -0.425; }, {"rolling_radius", "-0.425"}},
      {[](BogieCurvingParameters& p) { p.contact_half_distance = 0.0; }, {"contact_half_distance"}},
      {[](BogieCurvingParameters& p) { p.f11 = INFINITY; }, {"f11", "inf", "[N]"}},
      {[](BogieCurvingParameters& p) { p.f22 = 0.0; }, {"f22", "= 0 [N]"}},
      {[](BogieCurvingParameters& p) { p.gravitational_lateral_stiffness = -1.0; },
       {"gravitational_lateral_stiffness", "-1", ">= 0"}},
      {[](BogieCurvingParameters& p) { p.f23 = -5.0; }, {"f23", "-5", "[N m]"}},
      {[](BogieCurvingParameters& p) { p.f33 = -5.0; }, {"f33", "[N m^2]"}},
      {[&](BogieCurvingParameters& p) { p.contact_angle_slope = nan; }, {"contact_angle_slope", "[rad/m]"}},
      {[](BogieCurvingParameters& p) { p.primary_longitudinal_stiffness = -3.646e6; },
       {"primary_longitudinal_stiffness", "-3646000", "[N/m]"}},
      {[](BogieCurvingParameters& p) { p.primary_lateral_stiffness = -1.0; }, {"primary_lateral_stiffness", "-1"}},
      {[](BogieCurvingParameters& p) { p.primary_semi_spacing = 0.0; }, {"primary_semi_spacing", "= 0 [m]"}},
      {[](BogieCurvingParameters& p) { p.secondary_lateral_stiffness = -2.0; }, {"secondary_lateral_stiffness", "-2"}},
      {[](BogieCurvingParameters& p) { p.secondary_yaw_stiffness = -3.0; }, {"secondary_yaw_stiffness", "[N m/rad]"}},
      {[&](BogieCurvingParameters& p) { p.body_lateral_offset = nan; }, {"body_lateral_offset"}},
      {[&](BogieCurvingParameters& p) { p.body_yaw = nan; }, {"body_yaw", "[rad]"}},
      {[](BogieCurvingParameters& p) { p.primary_lateral_stiffness = p.secondary_lateral_stiffness = 0.0; },
       {"primary_lateral_stiffness", "secondary_lateral_stiffness", "laterally"}},
      {[](BogieCurvingParameters& p) {
         p.primary_lateral_stiffness = p.primary_longitudinal_stiffness = p.secondary_yaw_stiffness = 0.0;
       },
       {"primary_longitudinal_stiffness", "secondary_yaw_stiffness", "yaw"}},
  };
  for (const auto& [change, texts] : cases) {
    BogieCurvingParameters p = cooperrider();
    change(p);
    for (const std::function<void()>& call : {std::function<void()>([&] { p.validate(); }),
                                               std::function<void()>([&] { bogie_steady_curving(p); })}) {
      try {
        call();
        ADD_FAILURE() << "no exception, expected one naming " << texts.front();
      } catch (const std::invalid_argument& e) {
        for (const char* text : texts) EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
      }
    }
  }
  cooperrider().validate();  // the reference set itself is valid
}

}  // namespace
}  // namespace wrc
