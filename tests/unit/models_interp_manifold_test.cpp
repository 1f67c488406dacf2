// SPDX-License-Identifier: Apache-2.0
// The interpolated model on the rigid manifold (S1002/UIC60, the default table: 121 y x 3 yaw
// nodes, 3 roll nodes within +-2 mrad of the rigid roll): its rigid height against the exact rigid
// wheelset, its gap gradient against central differences of its own gap, and its kinematics
// (contact angle, rolling-radius difference) against the exact geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/geometry/rigid_wheelset.hpp"
#include "core/models/interpolated_model.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

const InterpolatedModel& model() {
  static const InterpolatedModel m(test::s1002_uic60_geometry());
  return m;
}

// Cells of the table in which the exact common point of a wheel jumps at yaw (a step of more than
// 1 mm in s between rigid solutions h/5 apart), or the exact rigid height's slope changes by more
// than 1 within the cell (the flange onset, |y| ~ 6.2-6.5 mm: the slope rises from 0.1 to 13 and
// falls back to 5 within 0.3 mm): marks[c] for cell c.
void mark_jump_cells(double yaw, std::vector<bool>& marks) {
  const ContactPointTable& t = model().table();
  const RigidWheelsetSolver solver(model().geometry());
  const int cells = t.y_node_count() - 1, per_cell = 5;
  RigidContact exact = solver.solve(t.y_node(0), yaw);
  for (int c = 0; c < cells; ++c) {
    const double h = t.y_node(c + 1) - t.y_node(c);
    double slope_low = 1e9, slope_high = -1e9;
    for (int q = 1; q <= per_cell; ++q) {
      const RigidContact previous = exact;
      exact = solver.solve(t.y_node(c) + h * q / per_cell, yaw, exact);
      if (std::fabs(exact.left().s - previous.left().s) > 1e-3 ||
          std::fabs(exact.right().s - previous.right().s) > 1e-3)
        marks[static_cast<size_t>(c)] = true;
      const double slope = (exact.pose.z - previous.pose.z) / (h / per_cell);
      slope_low = std::min(slope_low, slope);
      slope_high = std::max(slope_high, slope);
    }
    if (slope_high - slope_low > 1.0) marks[static_cast<size_t>(c)] = true;
  }
}

// The exact rigid wheelset and the interp one at 5 samples per y cell over the whole table, at one
// yaw. Jump cells: those in which the exact common point jumps at this yaw or at any yaw node (the
// yaw interpolation mixes every yaw node's values).
struct ManifoldScan {
  std::vector<double> y, z_exact, z_interp, roll_exact, roll_interp, angle_error, delta_r_error;
  std::vector<bool> in_jump_cell, near_jump_cell;  // the jump cell itself; it or a neighbour
  std::vector<double> jump_cells;                  // lower node of every jump cell [m]
};

ManifoldScan scan(double yaw) {
  const ContactPointTable& t = model().table();
  const RigidWheelsetSolver solver(model().geometry());
  const int cells = t.y_node_count() - 1, per_cell = 5;
  ManifoldScan m;
  std::vector<bool> jump(static_cast<size_t>(cells), false);
  mark_jump_cells(yaw, jump);
  for (int k = 0; k < t.grid().yaw_points; ++k) mark_jump_cells(t.yaw_node(k), jump);
  // The cells of a jump's band, at any yaw node (where the two points share the load the table
  // blends them by design, test (4)).
  for (const JumpTransition& j : t.jump_transitions())
    for (int c = 0; c < cells; ++c)
      if (t.y_node(c + 1) > j.y_low && t.y_node(c) < j.y_high) jump[static_cast<size_t>(c)] = true;
  for (int c = 0; c < cells; ++c)
    if (jump[static_cast<size_t>(c)]) m.jump_cells.push_back(t.y_node(c));
  RigidContact exact;
  for (int c = 0; c <= cells; ++c) {
    for (int q = 0; q < (c == cells ? 1 : per_cell); ++q) {
      const double y = c == cells ? t.y_node(c) : t.y_node(c) + (t.y_node(c + 1) - t.y_node(c)) * q / per_cell;
      exact = m.y.empty() ? solver.solve(y, yaw) : solver.solve(y, yaw, exact);
      m.y.push_back(y);
      m.z_exact.push_back(exact.pose.z);
      m.roll_exact.push_back(exact.pose.roll);
      const double roll = t.rigid_roll(y, yaw);
      m.roll_interp.push_back(roll);
      m.z_interp.push_back(t.rigid_height(y, yaw));
      const WheelsetPose pose{y, m.z_interp.back(), roll, yaw, 0.0};
      const ContactPoint l = t.at(WheelSide::kLeft, pose), r = t.at(WheelSide::kRight, pose);
      m.angle_error.push_back(std::max(std::fabs(l.contact_angle - exact.left().contact_angle),
                                       std::fabs(r.contact_angle - exact.right().contact_angle)));
      m.delta_r_error.push_back(std::fabs((l.rolling_radius - r.rolling_radius) - exact.delta_r()));
    }
  }
  for (size_t k = 0; k < m.y.size(); ++k) {
    const int c = std::min(cells - 1, static_cast<int>(k) / per_cell);
    const bool on_node = static_cast<int>(k) % per_cell == 0;
    // A node sample belongs to both neighbouring cells.
    const bool here = jump[static_cast<size_t>(c)] || (on_node && c > 0 && jump[static_cast<size_t>(c - 1)]);
    bool near = here;
    for (int d = -2; d <= 2; ++d) {
      const int n = c + d;
      if (n >= 0 && n < cells && jump[static_cast<size_t>(n)]) near = true;
    }
    m.in_jump_cell.push_back(here);
    m.near_jump_cell.push_back(near);
  }
  return m;
}

// (1) The interp gaps vanish together at (rigid_roll, rigid_height) outside the jumps' bands (in
// them the blend lifts a wheel by less than the band's half-width), which agrees with the exact
// rigid wheelset within 5 um away from jump cells (at the nodes of a yaw node to rounding), and is
// continuous across the jump cells. Measured (printed) at yaw 0 / 1.1043 mrad (the benchmark's
// end) / 5 / 10 mrad: at most 0.33 um (0.43 urad in roll) away from jump cells. The jump cells
// (mark_jump_cells()) are the centre (y = 0, the tread points change sides), the flange root
// (|y| ~ 4.9 mm) and the flange onset (|y| ~ 6.2-6.5 mm: the rigid height rises by 2.6 mm within
// 0.3 mm there, and the smoothed cells depart from the exact kinks by up to 0.2 mm).
TEST(InterpManifold, RigidHeightIsTheExactOneAwayFromJumps) {
  const ContactPointTable& t = model().table();
  for (double yaw : {0.0, 1.1043e-3, 5e-3, 10e-3}) {
    const ManifoldScan m = scan(yaw);
    double away = 0, at_nodes = 0, in_jumps = 0, roll_away = 0, gap = 0, gap_in_bands = 0, widest = 0;
    for (size_t k = 0; k < m.y.size(); ++k) {
      const double e = std::fabs(m.z_interp[k] - m.z_exact[k]);
      bool in_band = false;
      for (const JumpTransition& j : t.jump_transitions()) {
        in_band = in_band || (m.y[k] > j.y_low && m.y[k] < j.y_high);
        widest = std::max(widest, j.height_half_width);
      }
      if (k % 5 == 0 && !in_band) at_nodes = std::max(at_nodes, e);
      if (m.in_jump_cell[k]) {
        in_jumps = std::max(in_jumps, e);
      } else {
        away = std::max(away, e);
        roll_away = std::max(roll_away, std::fabs(m.roll_interp[k] - m.roll_exact[k]));
      }
      const WheelsetPose pose{m.y[k], m.z_interp[k], m.roll_interp[k], yaw, 0.0};
      double& worst = in_band ? gap_in_bands : gap;
      for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight})
        worst = std::max(worst, std::fabs(t.at(side, pose).distance));
    }
    // Continuity across every jump cell: sampled every 1 um, the interp rigid height never steps by
    // more than 20 um (a slope of 20; the exact one reaches ~14 at the flange, a jump of the
    // height would show as a step of its size).
    double step = 0;
    for (double y0 : m.jump_cells) {
      double previous = t.rigid_height(y0, yaw);
      for (int q = 1; q <= 250; ++q) {
        const double z = t.rigid_height(y0 + q * 1e-6, yaw);
        step = std::max(step, std::fabs(z - previous));
        previous = z;
      }
    }
    std::printf("yaw %.4g: |z - z_exact| away from jumps %.3g m (roll %.3g rad), at nodes %.3g m, in %zu jump "
                "cells %.3g m (largest step 1 um apart %.3g m); |gap| at the interp rigid pose %.3g m (in the "
                "jumps' bands %.3g m)\n",
                yaw, away, roll_away, at_nodes, m.jump_cells.size(), in_jumps, step, gap, gap_in_bands);
    EXPECT_LT(away, 5e-6) << yaw;
    EXPECT_LT(gap, 1e-12) << yaw;  // both gaps vanish at the interpolated rigid pose
    // In a band the blend lifts one wheel's touching height by at most the band's half-width.
    EXPECT_LE(gap_in_bands, widest) << yaw;
    if (yaw == 0.0 || yaw == 10e-3) {
      EXPECT_LT(at_nodes, 1e-11) << yaw;  // a yaw node: exact at every y node
    }
    EXPECT_LT(step, 20e-6) << yaw;
    EXPECT_LT(in_jumps, 0.5e-3) << yaw;
  }
}

// (2) The gap gradient is the exact derivative of the interpolated gap: central differences
// (step 1e-7 in each coordinate; rounding about 1e-16 x 0.5 m / 1e-7 = 5e-10 m/rad) agree within
// 1e-6 relative to the gradient's size (its largest component, the roll one, ~0.6 m/rad), just off
// the manifold (roll 1 um/rad above the rigid roll: a difference straddling the roll node delta = 0,
// where the gap is C1 but its second derivative jumps, errs by h |jump of d2/droll2| / 4, measured
// 6e-6 relative in a jump cell), inside the roll band, beyond it, between every kind of node and in
// jump cells.
TEST(InterpManifold, GapGradientIsTheDerivativeOfTheGap) {
  const ContactPointTable& t = model().table();
  const double h = 1e-7;
  double worst = 0;
  for (double y : {-9.3e-3, -5.3065e-3, -5.1e-3, -2.07e-3, 1.3e-4, 3.33e-3, 5.13e-3, 8.71e-3}) {
    for (double yaw : {-7.3e-3, 0.0, 1.1043e-3, 4.4e-3}) {
      for (double offset : {1e-6, 0.7e-3, -1.3e-3, 3.1e-3}) {
        const WheelsetPose pose{y, 0.46, t.rigid_roll(y, yaw) + offset, yaw, 0.0};
        for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
          const Eigen::Vector4d g = t.evaluate(side, pose).gap_gradient;
          for (int c = 0; c < 4; ++c) {
            WheelsetPose plus = pose, minus = pose;
            double* pc[4] = {&plus.y, &plus.z, &plus.roll, &plus.yaw};
            double* mc[4] = {&minus.y, &minus.z, &minus.roll, &minus.yaw};
            *pc[c] += h;
            *mc[c] -= h;
            const double fd = (t.at(side, plus).distance - t.at(side, minus).distance) / (2 * h);
            const double e = std::fabs(fd - g[c]) / g.cwiseAbs().maxCoeff();
            worst = std::max(worst, e);
            EXPECT_LT(e, 1e-6) << "y " << y << " yaw " << yaw << " offset " << offset << " coordinate " << c
                               << " gradient " << g[c] << " central difference " << fd;
          }
        }
      }
    }
  }
  std::printf("gap gradient against central differences: largest relative difference %.3g\n", worst);
}

// (3) On the manifold the kinematics are the exact geometry's away from jumps: contact angle and
// rolling-radius difference at the interp rigid pose against the exact rigid wheelset, 5 samples
// per cell, cells within 2 of a jump cell excluded (the monotone slopes reach 2 nodes). Bounds
// stated from the measured maxima (printed: 4.5e-5 rad and 0.43 um, against angles of 0.02-1.2 rad
// and differences up to 23 mm): the cubic interpolation error of the tabulated values over 1/6 mm
// cells.
TEST(InterpManifold, KinematicsAreTheExactOnesAwayFromJumps) {
  for (double yaw : {0.0, 1.1043e-3, 5e-3}) {
    const ManifoldScan m = scan(yaw);
    double angle = 0, delta_r = 0, angle_all = 0;
    for (size_t k = 0; k < m.y.size(); ++k) {
      angle_all = std::max(angle_all, m.angle_error[k]);
      if (m.near_jump_cell[k]) continue;
      angle = std::max(angle, m.angle_error[k]);
      delta_r = std::max(delta_r, m.delta_r_error[k]);
    }
    std::printf("yaw %.4g: away from jumps |contact angle error| %.3g rad, |delta r error| %.3g m (all: angle "
                "%.3g rad)\n",
                yaw, angle, delta_r, angle_all);
    EXPECT_LT(angle, 2e-4) << yaw;
    EXPECT_LT(delta_r, 1e-6) << yaw;
  }
}

// The local minimum other than the common point nearest to s_near (within 5 mm), its height above the
// common point at the exact rigid pose (y, yaw) [m]; -1 when there is none.
double second_point_height(WheelSide side, double y, double yaw, double s_near) {
  const RigidContact rigid = RigidWheelsetSolver(model().geometry()).solve(y, yaw);
  const ContactPoint& common = rigid.contact[static_cast<size_t>(side)];
  double best = -1, best_shift = 5e-3;
  for (const ContactPoint& p : model().geometry().potential_points(side, rigid.pose)) {
    if (!p.is_minimum || std::fabs(p.s - common.s) < 1e-9 || std::fabs(p.s - s_near) >= best_shift) continue;
    best_shift = std::fabs(p.s - s_near);
    best = p.distance - common.distance;
  }
  return best;
}

// (4) The table ramps from one point to the other over each unfolded jump's band, the y range in which an
// elastic wheel at the benchmark's load (77357.5 N per wheel) touches both minima: its ends are
// where the second minimum lies h above the common point (checked on the exact geometry; h the
// Hertz approach, or a branch's fold), they are table nodes (the uniform nodes inside stay and are
// blended), the bands of the two wheels mirror each other (mirror y and the wheels swap), and
// across the flange-root band the interpolated contact angle goes monotonically from one exact
// point's to the other's (the smooth maximum's gradient is a convex combination of the branches').
// Measured (printed): flange root h = 105.5 um, the approach, band 1.07 mm; centre h = 8.8 um, the
// tread minimum's fold (approach 82 um), band 0.48 mm: folded, no band in the table.
TEST(InterpManifold, JumpBandsAreWhereBothPointsCarryLoad) {
  const ContactPointTable& t = model().table();
  std::vector<JumpTransition> centre;
  int at_yaw0 = 0;
  for (const JumpTransition& j : t.jump_transitions()) {
    if (j.yaw != 0.0) continue;
    ++at_yaw0;
    // The mirrored jump of the other wheel.
    int mirrored = 0;
    for (const JumpTransition& m : t.jump_transitions())
      if (m.yaw == 0.0 && m.side != j.side && std::fabs(m.y + j.y) < 1e-7 && std::fabs(m.y_low + j.y_high) < 1e-7 &&
          std::fabs(m.y_high + j.y_low) < 1e-7 && std::fabs(m.height_half_width - j.height_half_width) < 1e-9)
        ++mirrored;
    EXPECT_EQ(mirrored, 1) << "jump at y " << j.y;
    // Both ends are nodes.
    int ends = 0;
    for (int i = 0; i < t.y_node_count(); ++i) ends += t.y_node(i) == j.y_low || t.y_node(i) == j.y_high;
    EXPECT_EQ(ends, 2) << j.y;
    EXPECT_LE(j.height_half_width, j.approach * (1 + 1e-12));
    if (std::fabs(j.y) < 1e-3) centre.push_back(j);
    if (std::fabs(std::fabs(j.y) - 5e-3) > 3e-4) continue;
    // Flange root: at each end the other branch lies h above (linear between the 10 um steps of
    // the walk: its height's curvature errs by far less than 0.5 um).
    const ContactPoint low = t.at(j.side, {j.y_low, 0.46, t.rigid_roll(j.y_low, 0.0), 0.0, 0.0});
    const ContactPoint high = t.at(j.side, {j.y_high, 0.46, t.rigid_roll(j.y_high, 0.0), 0.0, 0.0});
    const double h_low = second_point_height(j.side, j.y_low, 0.0, high.s);
    const double h_high = second_point_height(j.side, j.y_high, 0.0, low.s);
    std::printf("flange-root jump y %.4f mm: approach %.1f um, h %.1f um, band [%.4f, %.4f] mm, the other point "
                "%.2f / %.2f um above at its ends\n",
                j.y * 1e3, j.approach * 1e6, j.height_half_width * 1e6, j.y_low * 1e3, j.y_high * 1e3, h_low * 1e6,
                h_high * 1e6);
    EXPECT_NEAR(j.height_half_width, j.approach, 1e-12);
    EXPECT_NEAR(h_low, j.height_half_width, 0.5e-6);
    EXPECT_NEAR(h_high, j.height_half_width, 0.5e-6);
    // The contact angle on the manifold, every 5 um across the band, between the ends' values and
    // monotone.
    double previous = low.contact_angle;
    const double sign = high.contact_angle > low.contact_angle ? 1.0 : -1.0;
    for (double y = j.y_low; y <= j.y_high; y += 5e-6) {
      const double a = t.at(j.side, {y, 0.46, t.rigid_roll(y, 0.0), 0.0, 0.0}).contact_angle;
      EXPECT_GE(sign * (a - previous), -1e-12) << y;
      previous = a;
    }
  }
  // Per wheel the flange root; the flange onset's fold has no band, the centre's folded one keeps
  // the one-cell ramp.
  EXPECT_EQ(at_yaw0, 2);
  EXPECT_TRUE(centre.empty());
  // The centred jumps on the exact rigid line at yaw 0 (the table's uniform y nodes): a fold bounds
  // their h far below the approach.
  const RigidWheelsetSolver solver(model().geometry());
  std::vector<RigidContact> line;
  const InterpolationGrid& grid = t.grid();
  for (int i = 0; i < grid.y_points; ++i) {
    const double y = -grid.y_max + 2.0 * grid.y_max * i / (grid.y_points - 1);
    line.push_back(line.empty() ? solver.solve(y, 0.0) : solver.solve(y, 0.0, line.back()));
  }
  JumpTransitionOptions options;
  options.transition = grid.transition;
  options.transition_load = grid.transition_load;
  options.lateral_curvature_floor = ContactModelOptions{}.lateral_curvature_floor;
  for (const JumpTransition& j : find_jump_transitions(solver, line, 0.0, options)) {
    if (std::fabs(j.y) < 1e-3) {
      centre.push_back(j);
    } else {
      EXPECT_FALSE(j.folded) << j.y;
    }
  }
  ASSERT_EQ(centre.size(), 2u);
  for (const JumpTransition& j : centre) {
    EXPECT_TRUE(j.folded);
    std::printf("centred jump y %.4f mm: approach %.1f um, h %.2f um (fold), band [%.4f, %.4f] mm\n", j.y * 1e3,
                j.approach * 1e6, j.height_half_width * 1e6, j.y_low * 1e3, j.y_high * 1e3);
    EXPECT_LT(j.height_half_width, 0.5 * j.approach);  // the fold, not the approach, bounds it
    EXPECT_GT(j.y_high - j.y_low, 0.3e-3);
  }
}

// Outside the table the model refuses with OutsideModelError naming the coordinate; building the
// default table stays cheap (printed; the service builds it at start).
TEST(InterpManifold, OutsideTheTableAndPrecomputationTime) {
  const ContactPointTable& t = model().table();
  auto message = [&](const WheelsetPose& pose) -> std::string {
    try {
      t.at(WheelSide::kLeft, pose);
    } catch (const OutsideModelError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message({0.0105, 0.46, 0.0, 0.0, 0.0}).find("y = 0.0105"), std::string::npos);
  EXPECT_NE(message({0.0, 0.46, 0.0, 0.011, 0.0}).find("yaw = 0.011"), std::string::npos);
  EXPECT_NE(message({0.0, 0.46, 0.016, 0.0, 0.0}).find("roll = 0.016"), std::string::npos);
  EXPECT_EQ(message({0.0, 0.46, 0.004, 0.01, 0.0}), "");  // beyond the roll band: extrapolated
  std::printf("precomputation %.3f s\n", model().precomputation_seconds());  // a benchmark's number: printed
}

}  // namespace
}  // namespace wrc
