// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The force of the rail on one wheel, summed over that wheel's patches of a contact result, and what
/// a run reads off it (WheelOutput: Y, Q, creep forces, T gamma, p_max; docs/run-quantities.md).

#include <optional>

#include <Eigen/Core>

#include "core/dynamics/wheel_output.hpp"
#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// One wheel's patches summed. The normal part is kept per unit normal force, so that the run can
/// apply the normal force it reports (rigid contact: the constraint's, from the state) to it.
struct WheelForces {
  /// sum_p N_p n_p / N: the wheel's normal resultant per unit of the wheel's normal force N (the one
  /// wheel_forces() was given: a rigid wheel's constraint multiplier, by default sum_p N_p), track
  /// frame [-]. Unit in one-point contact and where a spline transition splits the wheel's N over
  /// the two branches' patches (their normal forces add up to N along the blend's normal, while
  /// sum_p N_p exceeds N); shorter than 1 for two separate contacts at different angles. Without a
  /// loaded patch the normal at the wheel's contact angle, (0, -side_sign sin delta, cos delta).
  Eigen::Vector3d normal_direction{0.0, 0.0, 1.0};
  double normal_force = 0;                   ///< sum_p N_p [N] (the patches' own normal forces)
  Eigen::Vector3d creep_force{0.0, 0.0, 0.0};  ///< sum_p (fx t1 + fy t2), track frame [N]
  double creep_force_x = 0;                  ///< sum_p fx [N]
  double creep_force_y = 0;                  ///< sum_p fy [N]
  double wear_number = 0;                    ///< sum_p |fx xi_x| + |fy xi_y| [N]
  double max_pressure = 0;                   ///< max_p 3 N_p / (2 pi a_p b_p) [Pa]

  /// The rail's force on the wheel with normal force N [N]: N normal_direction + creep_force, track frame [N].
  Eigen::Vector3d force(double n) const { return n * normal_direction + creep_force; }
};

/// The patches of wheel (0 left, 1 right) in contact summed (contact frame of contact_frame(n), as
/// add_to_resultant()). normal_force [N] is the wheel's normal force the patches carry: for rigid
/// contact the constraint's multiplier (sum over the wheel's constraints), which a spline transition
/// shares over two patches; left out, sum_p N_p (elastic contact, where each patch is its own force).
/// @throws std::invalid_argument when wheel is not 0 or 1, when normal_force is not finite and
/// positive while the wheel has a loaded patch, or as contact_frame() for a bad normal.
WheelForces wheel_forces(const ContactResult& contact, int wheel, std::optional<double> normal_force = std::nullopt);

/// a + w (b - a), member by member (the contact data between two accepted steps); w [-] in [0, 1].
WheelForces interpolate(const WheelForces& a, const WheelForces& b, double w);

/// Sets out's Y, Q, creep forces, T gamma and p_max from forces with the normal force N [N] (the one
/// the run reports: rigid contact the constraint's, elastic the patches'), for wheel 0 (left) or 1.
void set_force_outputs(const WheelForces& forces, double normal_force, int wheel, WheelOutput& out);

}  // namespace wrc
