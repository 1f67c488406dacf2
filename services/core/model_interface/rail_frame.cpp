// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/rail_frame.hpp"

#include <algorithm>
#include <cmath>

namespace wrc {
namespace {

// The axle A e_y of the pose's orientation Rz(yaw) Rx(roll) (wheelset_pose.hpp) and its
// derivatives by roll and yaw.
struct Axle {
  Eigen::Vector3d a, d_roll, d_yaw;
  explicit Axle(const WheelsetPose& pose) {
    const double cr = std::cos(pose.roll), sr = std::sin(pose.roll);
    const double cy = std::cos(pose.yaw), sy = std::sin(pose.yaw);
    a = Eigen::Vector3d(-sy * cr, cy * cr, sr);
    d_roll = Eigen::Vector3d(sy * sr, -cy * sr, cr);
    d_yaw = Eigen::Vector3d(-cy * cr, -sy * cr, 0.0);
  }
};

// Roll asin(a_z) and yaw atan2(-a_x, a_y) of a unit axle a.
double roll_of(const Eigen::Vector3d& a) { return std::asin(std::clamp(a.z(), -1.0, 1.0)); }
double yaw_of(const Eigen::Vector3d& a) { return std::atan2(-a.x(), a.y()); }
// Their changes for a change da of the axle.
double roll_change(const Eigen::Vector3d& a, const Eigen::Vector3d& da) {
  return da.z() / std::sqrt(a.x() * a.x() + a.y() * a.y());
}
double yaw_change(const Eigen::Vector3d& a, const Eigen::Vector3d& da) {
  return (a.x() * da.y() - a.y() * da.x()) / (a.x() * a.x() + a.y() * a.y());
}

Eigen::Matrix3d roll_matrix(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

}  // namespace

RailFrame::RailFrame(const RailOffset& offset, double pivot_y)
    : offset_(offset),
      rotation_(roll_matrix(offset.roll)),
      pivot_(0.0, pivot_y, 0.0),
      shift_(0.0, offset.lateral, offset.vertical) {}

Eigen::Vector3d RailFrame::to_rail_point(const Eigen::Vector3d& x) const {
  return rotation_.transpose() * (x - pivot_ - shift_) + pivot_;
}

WheelsetPose RailFrame::relative_pose(const WheelsetPose& pose) const {
  const Eigen::Vector3d centre = to_rail_point(Eigen::Vector3d(pose.x, pose.y, pose.z));
  const Eigen::Vector3d axle = rotation_.transpose() * Axle(pose).a;
  WheelsetPose r;
  r.x = pose.x;
  r.y = centre.y();
  r.z = centre.z();
  r.roll = roll_of(axle);
  r.yaw = yaw_of(axle);
  return r;
}

Eigen::Matrix4d RailFrame::pose_jacobian(const WheelsetPose& pose) const {
  const Eigen::Matrix3d rt = rotation_.transpose();
  const Axle axle(pose);
  const Eigen::Vector3d a = rt * axle.a;
  const Eigen::Vector3d a_roll = rt * axle.d_roll;
  const Eigen::Vector3d a_yaw = rt * axle.d_yaw;
  Eigen::Matrix4d j = Eigen::Matrix4d::Zero();
  j(0, 0) = rt(1, 1);
  j(0, 1) = rt(1, 2);
  j(1, 0) = rt(2, 1);
  j(1, 1) = rt(2, 2);
  j(2, 2) = roll_change(a, a_roll);
  j(2, 3) = roll_change(a, a_yaw);
  j(3, 2) = yaw_change(a, a_roll);
  j(3, 3) = yaw_change(a, a_yaw);
  return j;
}

Eigen::Vector4d RailFrame::pose_rate(const WheelsetPose& pose) const {
  // d R^T / dt = d R^T / d roll * roll_rate; R^T = roll_matrix(-roll).
  const double c = std::cos(offset_.roll), s = std::sin(offset_.roll);
  Eigen::Matrix3d d_rt;
  d_rt << 0, 0, 0, 0, -s, c, 0, -c, -s;
  d_rt *= offset_.roll_rate;
  const Eigen::Vector3d centre(pose.x, pose.y, pose.z);
  const Eigen::Vector3d shift_rate(0.0, offset_.lateral_rate, offset_.vertical_rate);
  const Eigen::Vector3d centre_rate = d_rt * (centre - pivot_ - shift_) - rotation_.transpose() * shift_rate;
  const Eigen::Vector3d axle = Axle(pose).a;
  const Eigen::Vector3d a = rotation_.transpose() * axle;
  const Eigen::Vector3d a_rate = d_rt * axle;
  return Eigen::Vector4d(centre_rate.y(), centre_rate.z(), roll_change(a, a_rate), yaw_change(a, a_rate));
}

double RailFrame::track_angle(double angle, WheelSide side) const {
  // The roll turns the left wheel's normal, (0, -sin a, cos a), to angle a + roll, the right one's
  // to a - roll.
  return angle + (side == WheelSide::kLeft ? offset_.roll : -offset_.roll);
}

WheelsetMotion RailFrame::to_rail(const WheelsetMotion& motion) const {
  WheelsetMotion m;
  m.centre = to_rail_point(motion.centre);
  m.velocity = rotation_.transpose() * motion.velocity;
  m.angular_velocity = rotation_.transpose() * motion.angular_velocity;
  return m;
}

ContactPoint RailFrame::to_track(ContactPoint point) const {
  point.wheel_point = rotation_ * (point.wheel_point - pivot_) + pivot_ + shift_;
  point.rail_point = rotation_ * (point.rail_point - pivot_) + pivot_ + shift_;
  point.normal = rotation_ * point.normal;
  point.contact_angle = track_angle(point.contact_angle, point.side);
  return point;
}

WheelConstraint RailFrame::to_track(WheelConstraint constraint, const WheelsetPose& pose, WheelSide side) const {
  const Eigen::Vector4d gradient = constraint.gap_gradient;
  constraint.gap_gradient = pose_jacobian(pose).transpose() * gradient;
  constraint.gap_rate += gradient.dot(pose_rate(pose));
  constraint.contact_angle = track_angle(constraint.contact_angle, side);
  return constraint;
}

}  // namespace wrc
