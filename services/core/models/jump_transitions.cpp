// SPDX-License-Identifier: Apache-2.0
#include "core/models/jump_transitions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/model_interface/jump_transition.hpp"
#include "core/model_interface/patch_builder.hpp"

namespace wrc {
namespace {

// The common point jumps between two rigid solutions when it moves by more than this in s [m]; a
// followed branch is the minimum within this of its previous s (its s moves by less than 0.5 mm per
// 0.01 mm of y on S1002/UIC60; a larger step means it has vanished).
constexpr double kJumpShift = 1e-3;
// Bisection stops when the bracket of the jump is this narrow [m].
constexpr double kJumpLocation = 1e-8;
// Farthest a branch is followed past its jump [m] (as the spline fit's continuation).
constexpr double kMaxTrace = 3e-3;

double approach_at(const ContactPoint& p, const JumpTransitionOptions& options) {
  const HertzShape shape = contact_shape(p, options.lateral_curvature_floor).shape;
  return sharing_approach(shape.A, shape.B, options.transition_load);
}

// Following one branch away from the jump: (distance from the jump [m], its touching height above
// the common point's [m]) at each step, and whether it vanished (a fold) before the walk ended.
struct Trace {
  std::vector<std::pair<double, double>> heights;
  bool vanished = false;
};

Trace follow_branch(const RigidWheelsetSolver& solver, WheelSide side, double yaw, double y_jump, int direction,
                    double s_start, double y_end, double stop_height, const JumpTransitionOptions& options,
                    RigidContact warm) {
  Trace trace;
  double s_prev = s_start;
  const int w = static_cast<int>(side);
  for (int n = 1;; ++n) {
    const double dy = n * options.trace_step, y = y_jump + direction * dy;
    if (dy > kMaxTrace || direction * (y - y_end) > 0) return trace;
    warm = solver.solve(y, yaw, warm);
    const ContactPoint& common = warm.contact[static_cast<size_t>(w)];
    const std::vector<ContactPoint> points = solver.geometry().potential_points(side, warm.pose, options.search);
    const ContactPoint* branch = nullptr;
    for (const ContactPoint& p : points) {
      if (!p.is_minimum || std::fabs(p.s - s_prev) >= kJumpShift || std::fabs(p.s - common.s) < 1e-9) continue;
      if (!branch || std::fabs(p.s - s_prev) < std::fabs(branch->s - s_prev)) branch = &p;
    }
    if (!branch) {
      trace.vanished = true;
      return trace;
    }
    s_prev = branch->s;
    const double height = branch->distance - common.distance;
    trace.heights.emplace_back(dy, height);
    if (height > stop_height) return trace;
  }
}

// Distance from the jump at which the trace's height first reaches h (linear between steps); the
// trace's last distance, or one step, where it never does.
double reach(const Trace& trace, double h, double step) {
  double dy_prev = 0, height_prev = 0;
  for (const auto& [dy, height] : trace.heights) {
    if (height >= h) return dy_prev + (h - height_prev) / (height - height_prev) * (dy - dy_prev);
    dy_prev = dy;
    height_prev = height;
  }
  return std::max(dy_prev, step);
}

}  // namespace

std::vector<JumpTransition> find_jump_transitions(const RigidWheelsetSolver& solver,
                                                  const std::vector<RigidContact>& rigid, double yaw,
                                                  const JumpTransitionOptions& options) {
  std::vector<JumpTransition> out;
  if (options.transition <= 0.0 || rigid.size() < 2) return out;
  const double y_first = rigid.front().pose.y, y_last = rigid.back().pose.y;
  for (size_t i = 0; i + 1 < rigid.size(); ++i) {
    for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
      const size_t w = static_cast<size_t>(side);
      const double s_low = rigid[i].contact[w].s, s_high = rigid[i + 1].contact[w].s;
      if (std::fabs(s_high - s_low) <= kJumpShift) continue;
      // Bisection: low keeps the lower-y branch, high the higher-y one.
      RigidContact low = rigid[i], high = rigid[i + 1];
      while (high.pose.y - low.pose.y > kJumpLocation) {
        RigidContact mid = solver.solve(0.5 * (low.pose.y + high.pose.y), yaw, low);
        const double s = mid.contact[w].s;
        (std::fabs(s - low.contact[w].s) < std::fabs(s - high.contact[w].s) ? low : high) = std::move(mid);
      }
      // A point that moves fast but continuously (onto the flange) is no jump.
      if (std::fabs(high.contact[w].s - low.contact[w].s) <= kJumpShift) continue;
      JumpTransition t;
      t.side = side;
      t.yaw = yaw;
      t.y = 0.5 * (low.pose.y + high.pose.y);
      t.approach = 0.5 * (approach_at(low.contact[w], options) + approach_at(high.contact[w], options));
      const double cap = std::min(t.approach, options.transition);
      // Past the jump upwards the lower-y branch lies above the common point, downwards the other.
      const Trace up = follow_branch(solver, side, yaw, t.y, +1, low.contact[w].s, y_last, cap, options, high);
      const Trace down = follow_branch(solver, side, yaw, t.y, -1, high.contact[w].s, y_first, cap, options, low);
      // A branch that vanishes within one step of the walk on either side (the flange onset's
      // fold) leaves a transition narrower than the walk resolves: no band.
      if (up.heights.empty() || down.heights.empty()) continue;
      double h = cap;
      for (const Trace* trace : {&up, &down})
        if (trace->vanished && !trace->heights.empty()) h = std::min(h, trace->heights.back().second);
      t.folded = h < cap;
      t.height_half_width = std::max(h, 1e-12);
      t.y_low = std::max(y_first, t.y - reach(down, t.height_half_width, options.trace_step));
      t.y_high = std::min(y_last, t.y + reach(up, t.height_half_width, options.trace_step));
      out.push_back(t);
    }
  }
  return out;
}

}  // namespace wrc
