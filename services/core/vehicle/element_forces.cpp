// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/element_forces.hpp"
#include "core/vehicle/rotations.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/vehicle/track_frames.hpp"

namespace wrc {
namespace {

// The axes of the three rotations of R = Rz(z) Ry(y) Rx(x), as columns (x, y, z): the angular
// velocity is J (x', y', z') in the frame R maps into (the roll axis Rz Ry e_x does not depend on
// the roll angle).
Eigen::Matrix3d rotation_axes(double y_angle, double z_angle) {
  const Eigen::Matrix3d rz = rotation_z(z_angle);
  Eigen::Matrix3d j;
  j.col(0) = rz * rotation_y(y_angle) * Eigen::Vector3d::UnitX();
  j.col(1) = rz * Eigen::Vector3d::UnitY();
  j.col(2) = Eigen::Vector3d::UnitZ();
  return j;
}

// One end of an element: a body's attachment point or a point of the track.
struct End {
  int body = -1;             // index in vehicle.bodies, -1 for the track
  FramePose to_station;      // its track frame in the station frame
  Eigen::Vector3d arm;       // [m] body: R p, from the centre of gravity in its track frame
  Eigen::Vector3d point;     // [m] in the station frame
  Eigen::Vector3d velocity;  // [m/s] in the station frame
  Eigen::Matrix3d orientation;       // [-] in the station frame
  Eigen::Vector3d angular_velocity;  // [rad/s] in the station frame
};

int body_index(const VehicleDescription& vehicle, const VehicleElement& e, int k) {
  const std::string& name = e.bodies[static_cast<std::size_t>(k)];
  if (name == kTrackBody) return -1;
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i)
    if (vehicle.bodies[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument("element '" + e.name + "': bodies: '" + name + "' is no body of the vehicle");
}

Eigen::Vector3d vec(const std::array<double, 3>& a) { return Eigen::Vector3d(a[0], a[1], a[2]); }

// The end's point, orientation and their rates in the station frame. frame_distance: the distance
// of the track frame the end's local quantities are given in [m].
void place(End& end, const TrackLayout& layout, double station, double frame_distance, double speed,
           const Eigen::Vector3d& local_point, const Eigen::Vector3d& local_velocity,
           const Eigen::Matrix3d& local_orientation, const Eigen::Vector3d& local_angular_velocity) {
  end.to_station = track_frame_pose(layout, station, frame_distance);
  const TrackFrameTwist own = track_frame_twist(layout, frame_distance);
  const TrackFrameTwist common = track_frame_twist(layout, station);
  const Eigen::Matrix3d& r = end.to_station.rotation;
  end.point = end.to_station.point(local_point);
  // Both frames slide along the track at V: the point moves with its own frame's twist and is seen
  // from a frame moving with the station's.
  end.velocity = r * (local_velocity + speed * (own.angular.cross(local_point) + own.linear)) -
                 speed * (common.angular.cross(end.point) + common.linear);
  end.orientation = r * local_orientation;
  end.angular_velocity = r * (local_angular_velocity + speed * own.angular) - speed * common.angular;
}

std::vector<ElementAction> evaluate(const VehicleDescription& vehicle, const TrackLayout& layout, double s_ref,
                                    double speed, const std::vector<BodyState>& states, std::vector<BodyLoads>* loads) {
  if (states.size() != vehicle.bodies.size())
    throw std::invalid_argument("element forces: " + std::to_string(states.size()) + " body states for " +
                                std::to_string(vehicle.bodies.size()) + " bodies");
  // Each body's pose in its own track frame, once.
  struct Pose {
    double distance;            // [m] s_b
    Eigen::Vector3d centre;     // [m] c
    Eigen::Vector3d velocity;   // [m/s] dc/dt
    Eigen::Matrix3d rotation;   // R
    Eigen::Vector3d angular_velocity;  // [rad/s]
  };
  std::vector<Pose> poses(vehicle.bodies.size());
  for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
    const VehicleBody& b = vehicle.bodies[i];
    const auto& q = states[i].displacement;
    const auto& v = states[i].rate;
    Pose& p = poses[i];
    p.distance = s_ref + b.position[0];
    p.centre = Eigen::Vector3d(0.0, b.position[1] + q[kBodyLateral], b.position[2] + q[kBodyVertical]);
    p.velocity = Eigen::Vector3d(0.0, v[kBodyLateral], v[kBodyVertical]);
    p.rotation = rotation_z(q[kBodyYaw]) * rotation_y(q[kBodyPitch]) * rotation_x(q[kBodyRoll]);
    p.angular_velocity =
        rotation_axes(q[kBodyPitch], q[kBodyYaw]) * Eigen::Vector3d(v[kBodyRoll], v[kBodyPitch], v[kBodyYaw]);
  }
  if (loads) loads->assign(vehicle.bodies.size(), BodyLoads{});

  std::vector<ElementAction> actions;
  actions.reserve(vehicle.elements.size());
  for (const VehicleElement& e : vehicle.elements) {
    std::array<End, 2> ends;
    for (int k = 0; k < 2; ++k) ends[static_cast<std::size_t>(k)].body = body_index(vehicle, e, k);
    if (ends[0].body < 0 && ends[1].body < 0)
      throw std::invalid_argument("element '" + e.name + "': bodies: both are the track");
    // The nominal distances of the two points and the station between them.
    std::array<double, 2> frame_distance{}, point_distance{};
    for (std::size_t k = 0; k < 2; ++k) {
      const int body = ends[k].body >= 0 ? ends[k].body : ends[1 - k].body;
      frame_distance[k] = poses[static_cast<std::size_t>(body)].distance;
      point_distance[k] = frame_distance[k] + e.attachments[k][0];
    }
    if ((e.kind == ElementKind::kBumpStop || e.kind == ElementKind::kNonlinearDamper) &&
        (e.direction < 0 || e.direction > 2))
      throw std::invalid_argument("element '" + e.name + "': direction: " + std::to_string(e.direction) +
                                  " is none of 0, 1, 2");
    ElementAction a;
    a.station = 0.5 * (point_distance[0] + point_distance[1]);
    for (std::size_t k = 0; k < 2; ++k) {
      End& end = ends[k];
      const Eigen::Vector3d p = vec(e.attachments[k]);
      if (end.body < 0) {  // a point of the track frame at the other body's distance
        end.arm.setZero();
        place(end, layout, a.station, frame_distance[k], speed, p, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
              Eigen::Vector3d::Zero());
      } else {
        const Pose& pose = poses[static_cast<std::size_t>(end.body)];
        end.arm = pose.rotation * p;
        place(end, layout, a.station, frame_distance[k], speed, pose.centre + end.arm,
              pose.velocity + pose.angular_velocity.cross(end.arm), pose.rotation, pose.angular_velocity);
      }
    }
    a.point_a = ends[0].point;
    a.point_b = ends[1].point;
    a.deflection = a.point_b - a.point_a;
    a.deflection_rate = ends[1].velocity - ends[0].velocity;
    switch (e.kind) {
      case ElementKind::kSpringDamper:
        for (int i = 0; i < 3; ++i)
          a.force[i] = e.stiffness[static_cast<std::size_t>(i)] * a.deflection[i] +
                       e.damping[static_cast<std::size_t>(i)] * a.deflection_rate[i];
        break;
      case ElementKind::kBumpStop:
        a.force[e.direction] = bump_stop_force(e.clearance, e.stop_stiffness, a.deflection[e.direction]);
        break;
      case ElementKind::kNonlinearDamper:
        a.force[e.direction] = nonlinear_damper_force(e.curve, a.deflection_rate[e.direction]);
        break;
      case ElementKind::kTorsionalSpring: {
        // The relative rotation Q = R_A^T R_B = Rz(yaw) Ry(pitch) Rx(roll), in A's axes.
        const Eigen::Matrix3d& ra = ends[0].orientation;
        const Eigen::Matrix3d q = ra.transpose() * ends[1].orientation;
        const double roll = std::atan2(q(2, 1), q(2, 2));
        const double pitch = std::asin(std::clamp(-q(2, 0), -1.0, 1.0));
        const double yaw = std::atan2(q(1, 0), q(0, 0));
        a.rotation = Eigen::Vector3d(roll, pitch, yaw);
        const Eigen::Matrix3d j = rotation_axes(pitch, yaw);
        const Eigen::Vector3d omega = ra.transpose() * (ends[1].angular_velocity - ends[0].angular_velocity);
        a.rotation_rate = j.partialPivLu().solve(omega);
        // The generalised moments dV/d(angle) (and the dampers' alike) on the relative angles; the
        // moment on B whose virtual work over B's virtual rotation is minus theirs is
        // -R_A J^-T g, so +R_A J^-T g on A.
        const Eigen::Vector3d g(e.roll_stiffness * roll + e.roll_damping * a.rotation_rate[0], 0.0,
                                e.yaw_stiffness * yaw + e.yaw_damping * a.rotation_rate[2]);
        a.moment = ra * j.transpose().partialPivLu().solve(g);
        break;
      }
    }
    if (loads) {
      for (std::size_t k = 0; k < 2; ++k) {
        const End& end = ends[k];
        if (end.body < 0) continue;
        const double sign = k == 0 ? 1.0 : -1.0;
        const Eigen::Matrix3d back = end.to_station.rotation.transpose();
        const Eigen::Vector3d f = back * (sign * a.force);
        BodyLoads& l = (*loads)[static_cast<std::size_t>(end.body)];
        l.force += f;
        l.moment += end.arm.cross(f) + back * (sign * a.moment);
      }
    }
    actions.push_back(a);
  }
  if (loads) {
    for (std::size_t i = 0; i < vehicle.bodies.size(); ++i) {
      BodyLoads& l = (*loads)[i];
      const auto& q = states[i].displacement;
      const Eigen::Matrix3d j = rotation_axes(q[kBodyPitch], q[kBodyYaw]);
      l.generalised[kBodyLateral] = l.force.y();
      l.generalised[kBodyVertical] = l.force.z();
      l.generalised[kBodyRoll] = l.moment.dot(j.col(0));
      l.generalised[kBodyPitch] = l.moment.dot(j.col(1));
      l.generalised[kBodyYaw] = l.moment.dot(j.col(2));
    }
  }
  return actions;
}

}  // namespace

std::vector<ElementAction> element_actions(const VehicleDescription& vehicle, const TrackLayout& layout, double s_ref,
                                           double speed, const std::vector<BodyState>& states) {
  return evaluate(vehicle, layout, s_ref, speed, states, nullptr);
}

std::vector<BodyLoads> element_loads(const VehicleDescription& vehicle, const TrackLayout& layout, double s_ref,
                                     double speed, const std::vector<BodyState>& states) {
  std::vector<BodyLoads> loads;
  evaluate(vehicle, layout, s_ref, speed, states, &loads);
  return loads;
}

double bump_stop_force(double clearance, double stiffness, double deflection) {
  const double beyond = std::abs(deflection) - clearance;
  if (!(beyond > 0.0)) return 0.0;
  return std::copysign(stiffness * beyond, deflection);
}

double nonlinear_damper_force(const std::vector<std::pair<double, double>>& curve, double velocity) {
  if (curve.size() < 2) throw std::invalid_argument("nonlinear damper: the curve needs two points or more");
  const double v = std::abs(velocity);
  std::size_t k = 1;  // the segment (k - 1, k) holding v, or the last one beyond it
  while (k + 1 < curve.size() && v > curve[k].first) ++k;
  const auto& [v0, f0] = curve[k - 1];
  const auto& [v1, f1] = curve[k];
  const double f = f0 + (f1 - f0) / (v1 - v0) * (v - v0);
  return velocity < 0.0 ? -f : f;
}

}  // namespace wrc
