// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Where a rigid-contact wheel's contact point jumps (docs/dynamics.md, "Contact-point jumps"): the
/// event functions IDA locates the jumps with, the switch of a wheel to another point (one-point
/// contact there, or two-point sliding on the switching surface), the release of a point of a
/// two-point contact, and the check that every followed point is the lowest before a restart.

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_contact.hpp"

namespace wrc {

/// One located switch of a wheel's contact point (or regime).
struct SwitchRecord {
  double t = 0;        ///< [s]
  int wheel = 0;       ///< 0 left, 1 right
  double s_from = 0;   ///< wheel coordinate before [m]
  double s_to = 0;     ///< after [m]
  int wheelset = 0;    ///< the wheelset's index in a vehicle (0 for the lone wheelset) [-]
};

/// The event functions of rigid contact: switch L, switch R, normal force L, normal force R,
/// second point's normal force L, R.
constexpr int kEventFunctionCount = 6;

/// The direction IDA watches each event function in (IdaSegment::root_direction): a switch
/// function or a normal force falling through 0; a second point's normal force both ways.
inline constexpr std::array<int, kEventFunctionCount> kEventDirections{-1, -1, -1, -1, 0, 0};

/// [m] how far a followed point may lie above the lowest minimum at an accepted step (root finding
/// stops within ~1e-15 m of the crossing); more is a switch the root finding did not see.
constexpr double kBranchTolerance = 1e-9;

/// The event functions at the state y with its contact c into g (kEventFunctionCount values).
void event_functions(const ContactResult& c, const double* y, const FollowedBranches& branches, double* g);

/// How far a followed point is above the lowest minimum (or past a fold) at the contact c, per
/// wheel [m] (<= 0 on the right branch): -switch_function.
std::array<double, 2> branch_excess(const ContactResult& c);

/// What a switch works on: the run's contact, the consistent values on its current branches, the
/// run's choice of two-point sliding (IntegratorSettings::two_point_sliding), the time [s],
/// where it records its switches and counts them (contact_switches, two_point_entries), and the
/// index of the wheelset its records name (0 for the lone wheelset).
struct SwitchingContext {
  WheelsetContact& contact;
  std::function<InitialisationContext()> initialisation;
  bool two_point_sliding;
  double t;
  std::vector<SwitchRecord>& log;
  RunCounters& counters;
  int wheelset;
};

/// Wheel i leaves its branch for the point at target_s [m] (an event, or a switch the branch
/// check found at a step): one-point contact on the target, or, where one-point contact would at
/// once switch back (the point it leaves is not separating and two-point contact loads both
/// points), rigid two-point contact on both: Filippov's sliding mode on the switching surface
/// (only with two-point sliding; without it, one-point contact on the target). Sets the
/// contact's branches and the state y (positions and velocities projected).
void switch_wheel(const SwitchingContext& context, int wheel, double target_s, std::vector<double>& y);

/// Releases the point of wheel i whose normal force fell to 0 (second: the second point).
void release_point(WheelsetContact& contact, int wheel, bool second, std::vector<double>& y);

/// The wheel in one-point contact whose normal force fell to 0 at the events info (one flag per
/// event function), or -1.
int wheel_lifting_off(const std::vector<int>& info, const FollowedBranches& branches);

/// The switches of the events info at the state y: a point of a two-point contact that unloads is
/// released, a wheel whose followed point stops being the lowest switches to the lowest.
void switch_at_events(const SwitchingContext& context, const std::vector<int>& info, std::vector<double>& y);

/// After the corrector failed at every step size: a wheel in two-point contact keeps its more
/// loaded point.
void keep_more_loaded_points(const SwitchingContext& context, std::vector<double>& y);

/// Projects y onto the constraints and switches every wheel whose followed point is not the lowest
/// (at most kMaxSwitchesPerEvent times; not without two-point sliding), until a restart may start
/// there. @throws std::runtime_error when no branch is the lowest after that many switches.
void settle_on_lowest_branches(const SwitchingContext& context, std::vector<double>& y);

}  // namespace wrc
