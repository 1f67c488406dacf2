// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/contact_switching.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/models/wheel_constraint.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Switches of one event: at most this many in a row before the run fails (a cycle).
constexpr int kMaxSwitchesPerEvent = 8;

// Whether the point from_s that wheel w leaves for one-point contact at y_pair (the branches of
// pair) separates: its gap rate under the one-point velocities > 0. valid: false when the pair
// is no two-point contact (the point it leaves is gone, or is not the lower one).
bool leaving_point_separates(WheelsetContact& contact, size_t w, double from_s, const std::vector<double>& y_pair,
                             bool& valid) {
  bool separates = true;
  valid = false;
  try {
    const ContactResult& c = contact.at(y_pair.data());
    const std::optional<WheelConstraint>& from = c.second_wheels[w];
    valid = from && std::abs(from->s_wheel - from_s) <= kBranchLostDistance && c.wheels[w].switch_function > 0.0;
    if (valid) {
      double rate = from->gap_rate;
      for (int k = 0; k < kPoseUnknowns; ++k) rate += from->gap_gradient[k] * y_pair[kPoseUnknowns + k];
      separates = rate > 0.0;
    }
  } catch (const ContactConfigurationError&) {
    valid = false;
  }
  return separates;
}

// The impact on both points of the pair did not separate them: the two-point contact's normal
// forces decide (both > 0: the sliding mode; one <= 0: that point leaves at once). y_pair holds
// the projected two-point state.
void settle_pair(const SwitchingContext& context, const FollowedBranches& pair, int wheel, double from_s, double load,
                 std::vector<double>& y_pair, std::vector<double>& y) {
  const size_t w = static_cast<size_t>(wheel);
  const double n_target = y_pair[kUnknownNormalLeft + wheel];
  const double n_from = y_pair[kUnknownSecondNormalLeft + wheel];
  if (n_target > 0.0 && n_from > 0.0) {
    ++context.counters.two_point_entries;
    y = std::move(y_pair);
    return;
  }
  FollowedBranches stay = pair;
  stay.second_s[w] = kNaN;
  if (!(n_from > 0.0)) {
    // The point it leaves unloads: one-point contact on the target with the impact's velocities.
    context.contact.set_branches(stay, y_pair);
    y_pair[kUnknownNormalLeft + wheel] = load;
    y = std::move(y_pair);
    return;
  }
  // The target unloads: it only touched; stay on the point it was on.
  stay.tracked_s[w] = from_s;
  context.contact.set_branches(stay, y_pair);
  y_pair[kUnknownNormalLeft + wheel] = load;
  y = std::move(y_pair);
}

// Records a switch of wheel i from s_from to s_to [m] at the context's time.
void record(const SwitchingContext& context, int wheel, double s_from, double s_to) {
  context.log.push_back({context.t, wheel, s_from, s_to, context.wheelset});
}

}  // namespace

void event_functions(const ContactResult& c, const double* y, const FollowedBranches& branches, double* g) {
  g[0] = c.wheels[0].switch_function;
  g[1] = c.wheels[1].switch_function;
  g[2] = y[kUnknownNormalLeft];
  g[3] = y[kUnknownNormalRight];
  g[4] = branches.two_point(0) ? y[kUnknownSecondNormalLeft] : 1.0;
  g[5] = branches.two_point(1) ? y[kUnknownSecondNormalRight] : 1.0;
}

std::array<double, 2> branch_excess(const ContactResult& c) {
  return {-c.wheels[0].switch_function, -c.wheels[1].switch_function};
}

void switch_wheel(const SwitchingContext& context, int wheel, double target_s, std::vector<double>& y) {
  WheelsetContact& contact = context.contact;
  const size_t w = static_cast<size_t>(wheel);
  // The point it leaves can pair with the target only in one-point contact (a two-point
  // contact's events leave it for a third point or the survivor of a fold).
  const FollowedBranches before = contact.branches();
  const double from_s = before.two_point(wheel) ? kNaN : before.tracked_s[w];
  const std::vector<double> y_before = y;
  const double load = y[kUnknownNormalLeft + wheel] +
                      (before.two_point(wheel) ? y[kUnknownSecondNormalLeft + wheel] : 0.0);
  FollowedBranches single = before;
  single.tracked_s[w] = target_s;
  single.second_s[w] = kNaN;
  // One-point contact on the target: positions onto its gap, velocities onto its constraint
  // (an inelastic impact).
  std::vector<double> y_single = y_before;
  contact.set_branches(single, y_single);
  y_single[kUnknownNormalLeft + wheel] = load;
  project_positions(context.initialisation(), y_single);
  project_velocities(context.initialisation(), y_single);
  // Without two-point sliding (the run's choice) one-point contact on the target is the answer
  // whatever the point it leaves does next: the chattering of the paper's figures 5 and 6.
  if (std::isnan(from_s) || !context.two_point_sliding) {
    y = std::move(y_single);
    return;
  }
  // Would the point it leaves separate? Its gap rate under the one-point velocities.
  FollowedBranches pair = single;
  pair.second_s[w] = from_s;
  std::vector<double> y_pair = y_single;
  contact.set_branches(pair, y_pair);
  bool pair_valid = false;
  const bool from_separates = leaving_point_separates(contact, w, from_s, y_pair, pair_valid);
  if (!pair_valid || from_separates) {
    contact.set_branches(single, y_single);
    y = std::move(y_single);
    return;
  }
  // Not separating: the impact acts on both points.
  y_pair = y_before;
  contact.set_branches(pair, y_pair);
  y_pair[kUnknownNormalLeft + wheel] = 0.5 * load;
  y_pair[kUnknownSecondNormalLeft + wheel] = 0.5 * load;
  std::vector<double> yp_pair;
  try {
    project_positions(context.initialisation(), y_pair);
    project_velocities(context.initialisation(), y_pair);
    consistent_derivatives(context.initialisation(), y_pair, yp_pair);
  } catch (const std::exception&) {
    contact.set_branches(single, y_single);
    y = std::move(y_single);
    return;
  }
  settle_pair(context, pair, wheel, from_s, load, y_pair, y);
}

void release_point(WheelsetContact& contact, int wheel, bool second, std::vector<double>& y) {
  const size_t w = static_cast<size_t>(wheel);
  FollowedBranches next = contact.branches();
  const double remaining_load = second ? y[kUnknownNormalLeft + wheel] : y[kUnknownSecondNormalLeft + wheel];
  if (!second) next.tracked_s[w] = next.second_s[w];
  next.second_s[w] = kNaN;
  contact.set_branches(next, y);
  y[kUnknownNormalLeft + wheel] = remaining_load;
}

int wheel_lifting_off(const std::vector<int>& info, const FollowedBranches& branches) {
  for (int i = 0; i < 2; ++i)
    if (info[static_cast<size_t>(2 + i)] != 0 && !branches.two_point(i)) return i;
  return -1;
}

void switch_at_events(const SwitchingContext& context, const std::vector<int>& info, std::vector<double>& y) {
  WheelsetContact& contact = context.contact;
  const ContactResult c = contact.at(y.data());
  for (int i = 0; i < 2; ++i) {
    const size_t w = static_cast<size_t>(i);
    const FollowedBranches& branches = contact.branches();
    if (branches.two_point(i) && (info[2 + w] != 0 || info[4 + w] != 0)) {
      // One point of a two-point contact unloads: the sliding mode ends, the other point carries on.
      const bool second = info[4 + w] != 0;
      const double released = second ? branches.second_s[w] : branches.tracked_s[w];
      const double kept = second ? branches.tracked_s[w] : branches.second_s[w];
      record(context, i, released, kept);
      release_point(contact, i, second, y);
      ++context.counters.contact_switches;
      continue;
    }
    if (info[w] == 0) continue;
    const WheelConstraint& wc = c.wheels[w];
    record(context, i, wc.s_wheel, wc.switch_s_wheel);
    switch_wheel(context, i, wc.switch_s_wheel, y);
    ++context.counters.contact_switches;
  }
}

void keep_more_loaded_points(const SwitchingContext& context, std::vector<double>& y) {
  WheelsetContact& contact = context.contact;
  for (int i = 0; i < 2; ++i) {
    const FollowedBranches& branches = contact.branches();
    if (!branches.two_point(i)) continue;
    const size_t w = static_cast<size_t>(i);
    const bool second = y[static_cast<size_t>(kUnknownSecondNormalLeft + i)] < y[static_cast<size_t>(kUnknownNormalLeft + i)];
    const double released = second ? branches.second_s[w] : branches.tracked_s[w];
    const double kept = second ? branches.tracked_s[w] : branches.second_s[w];
    record(context, i, released, kept);
    release_point(contact, i, second, y);
    ++context.counters.contact_switches;
  }
}

void settle_on_lowest_branches(const SwitchingContext& context, std::vector<double>& y) {
  WheelsetContact& contact = context.contact;
  // A new segment starts with every followed point the lowest (the projections may have moved
  // another one below it): switch again until it does.
  for (int round = 0;; ++round) {
    contact.clear_cache();
    project_positions(context.initialisation(), y);
    project_velocities(context.initialisation(), y);
    const ContactResult c = contact.at(y.data());
    const std::array<double, 2> excess = branch_excess(c);
    int wrong = -1;
    for (int i = 0; i < 2 && wrong < 0; ++i)
      if (excess[static_cast<size_t>(i)] > kBranchTolerance) wrong = i;
    // Without two-point sliding the wheel stays where the switch put it: switching back at once
    // would chatter without end (docs/dynamics.md).
    if (wrong < 0 || !context.two_point_sliding) return;
    if (round >= kMaxSwitchesPerEvent) {
      std::ostringstream msg;
      msg << "the " << (wrong == 0 ? "left" : "right") << " wheel's contact point finds no branch that is the lowest"
          << " at t = " << exact_number_text(context.t) << " s after " << kMaxSwitchesPerEvent << " switches";
      throw std::runtime_error(msg.str());
    }
    const WheelConstraint& wc = c.wheels[static_cast<size_t>(wrong)];
    record(context, wrong, wc.s_wheel, wc.switch_s_wheel);
    switch_wheel(context, wrong, wc.switch_s_wheel, y);
    ++context.counters.contact_switches;
  }
}

}  // namespace wrc
