// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The rigid-body motion of the wheelset that the creepages need, from a ContactQuery.

#include <Eigen/Core>

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// Centre, velocity and angular velocity of the wheelset, track frame.
/// Orientation A = Rz(yaw) Rx(roll) (wheelset_pose.hpp). The angular velocity is
///   omega = roll_dot e_x' + spin_rate e_axle + yaw_dot e_z,
/// with e_x' = Rz(yaw) e_x (the roll axis) and e_axle = A e_y; forward rolling has spin_rate = +V/r0.
/// The centre moves with v_G = (V, y_dot, z_dot).
struct WheelsetMotion {
  Eigen::Vector3d centre{0, 0, 0};            ///< wheelset centre (x, y, z) [m]
  Eigen::Vector3d velocity{0, 0, 0};          ///< v_G [m/s]
  Eigen::Vector3d angular_velocity{0, 0, 0};  ///< omega [rad/s]

  /// From the pose, rates and speed of the query (not validated here).
  static WheelsetMotion from_query(const ContactQuery& query);
};

}  // namespace wrc
