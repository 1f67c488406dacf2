// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What a run reports of one wheel's contact at an output time or step (docs/run-quantities.md:
/// definitions, frames and signs).

#include <limits>

namespace wrc {

/// Y / Q of a wheel from its lateral force Y [N] and vertical force Q [N] (WheelOutput's signs) [-];
/// NaN when Q <= 0 (no vertical load on the wheel).
inline double y_over_q(double lateral_force, double vertical_force) {
  return vertical_force > 0.0 ? lateral_force / vertical_force : std::numeric_limits<double>::quiet_NaN();
}

/// The track-shift force of the axle from the wheels' Y [N]: the lateral force of the wheelset on
/// the track, track frame, positive to the left (+y) [N]: -(sum of the rail forces' y components)
/// = Y_left - Y_right.
inline double track_shift_force(double lateral_force_left, double lateral_force_right) {
  return lateral_force_left - lateral_force_right;
}

/// Contact of one wheel at an output time. Forces are those of the rail on the wheel; "track frame":
/// x forward, y to the left, z up of the track at the wheelset (docs/conventions.md).
struct WheelOutput {
  double s_wheel = 0;        ///< wheel profile coordinate of the contact point [m]
  double contact_angle = 0;  ///< [rad]
  double normal_force = 0;   ///< [N] (elastic: sum over the wheel's patches)
  /// Y: lateral force of the rail on the wheel, track frame, positive towards the track centre
  /// (the wheel pushes its rail outwards, as in flange contact): -y component on the left wheel,
  /// +y component on the right [N]. Sum over the patches of N n + fx t1 + fy t2.
  double lateral_force = 0;
  double vertical_force = 0;  ///< Q: vertical force of the rail on the wheel, track frame, positive upward [N]
  double creep_force_x = 0;   ///< sum over the patches of fx, along each patch's t1 (rolling direction) [N]
  double creep_force_y = 0;   ///< sum over the patches of fy, along each patch's t2 (lateral, contact plane) [N]
  /// T gamma: sum over the patches of |fx xi_x| + |fy xi_y| (no spin term) [N], the frictional power
  /// per unit distance rolled [J/m].
  double wear_number = 0;
  double max_pressure = 0;    ///< p_max: largest Hertz pressure 3 N / (2 pi a b) over the patches [Pa]

  /// Y / Q [-]; NaN when Q <= 0.
  double y_over_q() const { return wrc::y_over_q(lateral_force, vertical_force); }
};

}  // namespace wrc
