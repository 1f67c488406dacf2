#include "core/models/wheel_constraint.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

namespace wrc {

PoseAxes PoseAxes::at(const WheelsetPose& pose) {
  const double cpsi = std::cos(pose.yaw), spsi = std::sin(pose.yaw);
  const double cphi = std::cos(pose.roll), sphi = std::sin(pose.roll);
  return {Eigen::Vector3d(cpsi, spsi, 0.0), Eigen::Vector3d::UnitZ(), Eigen::Vector3d(-spsi * cphi, cpsi * cphi, sphi)};
}

Eigen::Vector4d vertical_gap_gradient(const ContactPoint& point, const WheelsetPose& pose) {
  const Eigen::Vector3d& n = point.normal;
  const Eigen::Vector3d rho = point.wheel_point - Eigen::Vector3d(pose.x, pose.y, pose.z);
  const PoseAxes axes = PoseAxes::at(pose);
  const double inv_nz = 1.0 / n.z();
  return Eigen::Vector4d(n.y() * inv_nz, 1.0, axes.roll.cross(rho).dot(n) * inv_nz,
                         axes.yaw.cross(rho).dot(n) * inv_nz);
}

WheelConstraint exact_point_constraint(const ContactPoint& point, const WheelsetPose& pose, double switch_function,
                                       double switch_s_wheel) {
  WheelConstraint c;
  c.gap = point.distance;
  c.gap_gradient = vertical_gap_gradient(point, pose);
  c.normal_z = point.normal.z();
  c.s_wheel = point.s;
  c.contact_angle = point.contact_angle;
  c.switch_function = switch_function;
  c.switch_s_wheel = switch_s_wheel;
  return c;
}

TrackedBranch track_branch(const std::vector<ContactPoint>& points, double tracked_s) {
  const size_t none = points.size();
  size_t followed = none;
  for (size_t k = 0; k < points.size(); ++k) {
    if (!points[k].is_minimum) continue;
    if (followed == none) {
      followed = k;
    } else if (std::isnan(tracked_s) ? points[k].distance < points[followed].distance
                                     : std::abs(points[k].s - tracked_s) < std::abs(points[followed].s - tracked_s)) {
      followed = k;
    }
  }
  if (followed == none) throw std::invalid_argument("track_branch: no local minimum among the potential points");
  TrackedBranch branch;
  branch.index = followed;
  branch.switch_s_wheel = std::numeric_limits<double>::quiet_NaN();
  if (!std::isnan(tracked_s) && std::abs(points[followed].s - tracked_s) > kBranchLostDistance) {
    // The followed minimum has merged with a maximum and vanished: an event at once, onto the
    // lowest minimum there is.
    size_t lowest = followed;
    for (size_t k = 0; k < points.size(); ++k)
      if (points[k].is_minimum && points[k].distance < points[lowest].distance) lowest = k;
    branch.switch_function = -kBranchLostDistance;
    branch.switch_s_wheel = points[lowest].s;
    return branch;
  }
  const double d = points[followed].distance;
  for (size_t k = 0; k < points.size(); ++k) {
    if (k == followed || !points[k].is_minimum) continue;
    if (std::isnan(branch.switch_s_wheel) || points[k].distance - d < branch.switch_function) {
      branch.switch_function = std::min(kNoSwitch, points[k].distance - d);
      branch.switch_s_wheel = points[k].s;
    }
  }
  for (size_t k : {followed - 1, followed + 1}) {  // followed - 1 wraps to a huge index at 0
    if (k < points.size() && !points[k].is_minimum)
      branch.switch_function = std::min(branch.switch_function, points[k].distance - d);
  }
  return branch;
}

}  // namespace wrc
