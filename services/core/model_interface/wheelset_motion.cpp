// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/wheelset_motion.hpp"

#include <cmath>

namespace wrc {

WheelsetMotion WheelsetMotion::from_query(const ContactQuery& q) {
  const double cpsi = std::cos(q.pose.yaw), spsi = std::sin(q.pose.yaw);
  const double cphi = std::cos(q.pose.roll), sphi = std::sin(q.pose.roll);
  const Eigen::Vector3d roll_axis(cpsi, spsi, 0.0);
  const Eigen::Vector3d axle(-spsi * cphi, cpsi * cphi, sphi);  // A * e_y
  WheelsetMotion m;
  m.centre = Eigen::Vector3d(q.pose.x, q.pose.y, q.pose.z);
  m.velocity = Eigen::Vector3d(q.speed, q.y_dot, q.z_dot);
  m.angular_velocity = q.roll_dot * roll_axis + q.spin_rate * axle + q.yaw_dot * Eigen::Vector3d::UnitZ();
  return m;
}

}  // namespace wrc
