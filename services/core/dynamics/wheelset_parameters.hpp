// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Everything a wheelset run needs besides the contact model: the wheelset's masses, the loads,
/// the primary suspension, the initial state and the integrator settings (issue-level names
/// shared by the parameter file, run_command_t and `wrc run`).

#include <string>

#include "core/dynamics/safety_limits.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/track/track_irregularity.hpp"
#include "core/track/track_layout.hpp"

namespace wrc {

/// Primary suspension of the wheelset to a frame that moves along the track at the wheelset's
/// speed, centred (y = 0, roll = yaw = 0) at the height of the centred wheelset in contact: two
/// axle boxes at +-half_spacing from the centre, each with a longitudinal, a lateral and a
/// vertical spring and damper. The longitudinal springs give the yaw restraint 2 k_x b^2, the
/// vertical ones the roll restraint 2 k_z b^2. Every value may be 0.
struct PrimarySuspension {
  double longitudinal_stiffness = 0;  ///< k_x per axle box [N/m]
  double lateral_stiffness = 0;       ///< k_y per axle box [N/m]
  double vertical_stiffness = 0;      ///< k_z per axle box [N/m]
  double longitudinal_damping = 0;    ///< c_x per axle box [N s/m]
  double lateral_damping = 0;         ///< c_y per axle box [N s/m]
  double vertical_damping = 0;        ///< c_z per axle box [N s/m]
  double half_spacing = 1.0;          ///< b, lateral distance of each axle box from the centre [m]

  /// The benchmark's suspension (docs/dynamics.md explains the choice).
  static PrimarySuspension benchmark();
  /// No suspension: the wheelset is free but for its constant forward speed.
  static PrimarySuspension none() { return {}; }
};

/// The rigid wheelset and its loads.
struct WheelsetParameters {
  double mass = 1813.0;          ///< m [kg]
  double roll_inertia = 1120.0;  ///< I_xx about the roll axis [kg m^2]
  double yaw_inertia = 1120.0;   ///< I_zz about the vertical axis [kg m^2]
  double spin_inertia = 112.0;   ///< I_yy about the axle [kg m^2]
  double speed = 30.0;           ///< constant forward speed V [m/s], > 0
  double vertical_force = 154715.0;  ///< external vertical load on the axle, downward [N]
  /// External lateral load, towards the left rail (+y) [N]. The benchmark's 20 kN push towards
  /// the right rail, so that, as in the paper, the right wheel reaches the flange root.
  double lateral_force = -20000.0;
  bool include_gravity = true;       ///< m g acts on top of vertical_force
  double gravity = 9.81;             ///< g [m/s^2]
  PrimarySuspension suspension = PrimarySuspension::benchmark();
  ContactMaterial material;          ///< G, nu, mu of wheel and rail
  int fastsim_elements = 20;         ///< FASTSIM elements per strip [-]
  int fastsim_strips = 20;           ///< FASTSIM strips [-]
  /// Largest flange angle of the wheel profile, for Nadal's Y/Q limit only [rad], in (0, pi/2)
  /// (docs/run-quantities.md); the default is S1002's, 70 deg.
  double flange_angle = kS1002FlangeAngle;

  /// Total downward load the contacts carry at rest: vertical_force (+ m g) [N].
  double total_vertical_load() const { return vertical_force + (include_gravity ? mass * gravity : 0.0); }
  /// @throws std::invalid_argument naming the first value that is not finite or out of range.
  void validate() const;
};

/// Where the run starts. z and roll follow from the contact (rigid: both wheels touching;
/// elastic: the static penetration), the spin rate is V / r0 + spin_rate_offset.
struct InitialState {
  double y = 0;         ///< lateral shift [m]
  double yaw = 0;       ///< yaw angle [rad]
  double y_dot = 0;     ///< lateral velocity [m/s]
  double yaw_dot = 0;   ///< yaw rate [rad/s]
  double spin_rate_offset = 0;  ///< spin rate minus V / r0 [rad/s]
  void validate() const;
};

/// Largest max_steps [-] (run_parameter_table()'s range [1, kMaxRunSteps]): 5e5 times the default,
/// and a whole number that a double and the message's int64 hold exactly.
inline constexpr double kMaxRunSteps = 1e12;

/// Time integration (SUNDIALS IDA, BDF of variable order and step).
struct IntegratorSettings {
  /// [-] most output samples of one run: t_end / output_period may not exceed it (200 s at the
  /// default 1 ms; publishing a sample takes some 30 us, so even all of them in one step stay a
  /// few seconds).
  static constexpr long kMaxOutputSamples = 200000;
  double t_end = 2.0;                 ///< simulated end time [s], > 0
  double relative_tolerance = 1e-6;   ///< rtol [-]
  double position_tolerance = 1e-8;   ///< atol of y, z [m] and roll, yaw [rad]
  double velocity_tolerance = 1e-6;   ///< atol of the rates [m/s, rad/s]
  double max_step = 0.01;             ///< largest step [s]
  double output_period = 1e-3;        ///< simulated time between output samples [s], > 0, t_end / it <= kMaxOutputSamples
  long max_steps = 2000000;           ///< steps before the run fails [-]
  /// Rigid contact: where one-point contact would chatter between two equally low minima of a
  /// wheel's distance (the one-point vector field pushing towards the switching surface from both
  /// sides), the wheel slides in rigid two-point contact (Filippov), and after every step each
  /// followed point is the lowest (docs/dynamics.md). false: the paper's one-point contact of its
  /// figures 5 and 6: a switch (an impact and an integrator restart) at each root of the event
  /// function only, no two-point contact and no branch check, so a followed point may lie above
  /// the lowest (the counter max_branch_excess says how far) and the run depends on rounding [-].
  bool two_point_sliding = true;
  /// The accepted step's contact query carries the next step's first state and Newton matrix
  /// (docs/dynamics.md, "Rigid contact"): the same run in fewer round trips. Not a run parameter:
  /// false only to compare the two (tests) [-].
  bool contact_ahead = true;
  void validate() const;
};

/// A whole run.
struct RunSpec {
  WheelsetParameters wheelset;
  InitialState initial;
  IntegratorSettings integrator;
  /// The track the wheelset runs on (default: straight and level); the wheelset starts at its
  /// s = 0 and travels s = speed * t.
  TrackLayout track;
  /// The track's irregularities along the same s (default: none); the cross-level is measured over
  /// the layout's cant base.
  TrackIrregularity irregularity;
  void validate() const;
};

}  // namespace wrc
