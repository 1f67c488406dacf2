// SPDX-License-Identifier: Apache-2.0
#include "core/models/wheel_constraint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

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

TwoPointBranches track_two_point(const std::vector<ContactPoint>& points, double tracked_s, double second_s) {
  const size_t none = points.size();
  auto nearest = [&](double s, size_t excluded) {
    size_t best = none;
    for (size_t k = 0; k < points.size(); ++k) {
      if (!points[k].is_minimum || k == excluded) continue;
      if (best == none || std::abs(points[k].s - s) < std::abs(points[best].s - s)) best = k;
    }
    return best;
  };
  const size_t first = nearest(tracked_s, none);
  if (first == none) throw std::invalid_argument("track_two_point: no local minimum among the potential points");
  const size_t second = nearest(second_s, first);
  TwoPointBranches pair;
  pair.first = first;
  pair.second = second == none ? first : second;
  const bool first_lost = std::abs(points[first].s - tracked_s) > kBranchLostDistance;
  const bool second_lost = second == none || std::abs(points[second].s - second_s) > kBranchLostDistance;
  if (first_lost || second_lost) {
    size_t target = first;
    if (first_lost && !second_lost) {
      target = second;
    } else if (first_lost) {
      for (size_t k = 0; k < points.size(); ++k)
        if (points[k].is_minimum && points[k].distance < points[target].distance) target = k;
    }
    pair.switch_function = -kBranchLostDistance;
    pair.switch_s_wheel = points[target].s;
    return pair;
  }
  const double lower = std::min(points[first].distance, points[second].distance);
  pair.switch_function = kNoSwitch;
  pair.switch_s_wheel = points[first].s;
  for (size_t k = 0; k < points.size(); ++k) {
    if (k == first || k == second || !points[k].is_minimum) continue;
    if (points[k].distance - lower < pair.switch_function) {
      pair.switch_function = points[k].distance - lower;
      pair.switch_s_wheel = points[k].s;
    }
  }
  for (const auto& [member, other] : {std::pair{first, second}, std::pair{second, first}}) {
    for (size_t k : {member - 1, member + 1}) {  // member - 1 wraps to a huge index at 0
      if (k >= points.size() || points[k].is_minimum) continue;
      if (points[k].distance - points[member].distance < pair.switch_function) {
        pair.switch_function = points[k].distance - points[member].distance;
        pair.switch_s_wheel = points[other].s;
      }
    }
  }
  return pair;
}

}  // namespace wrc
