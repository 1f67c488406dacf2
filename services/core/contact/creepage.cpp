// SPDX-License-Identifier: Apache-2.0
#include "core/contact/creepage.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wrc {
namespace {

void require_finite(const Eigen::Vector3d& v, const char* name) {
  if (!v.allFinite()) {
    std::ostringstream msg;
    msg << "creepages: " << name << " (" << v.x() << ", " << v.y() << ", " << v.z() << ") is not finite";
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

ContactFrame contact_frame(const Eigen::Vector3d& normal) {
  const double length = normal.norm();
  if (!std::isfinite(length) || !(length > 0.0)) {
    std::ostringstream msg;
    msg << "contact_frame: normal (" << normal.x() << ", " << normal.y() << ", " << normal.z()
        << ") is not a finite non-zero vector";
    throw std::invalid_argument(msg.str());
  }
  ContactFrame f;
  f.n = normal / length;
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX() - f.n.x() * f.n;
  const double t1_length = t1.norm();
  if (t1_length < 1e-6) {
    std::ostringstream msg;
    msg << "contact_frame: normal (" << normal.x() << ", " << normal.y() << ", " << normal.z()
        << ") is parallel to the track's x axis; the contact plane has no longitudinal direction";
    throw std::invalid_argument(msg.str());
  }
  f.t1 = t1 / t1_length;
  f.t2 = f.n.cross(f.t1);
  return f;
}

Creepages creepages(double forward_speed, const Eigen::Vector3d& centre_velocity,
                    const Eigen::Vector3d& angular_velocity, const Eigen::Vector3d& contact_point,
                    const Eigen::Vector3d& normal) {
  if (!(forward_speed > 0.0) || !std::isfinite(forward_speed)) {
    std::ostringstream msg;
    msg << "creepages: forward speed V = " << forward_speed << " m/s must be positive and finite";
    throw std::invalid_argument(msg.str());
  }
  require_finite(centre_velocity, "centre velocity");
  require_finite(angular_velocity, "angular velocity");
  require_finite(contact_point, "contact point");
  require_finite(normal, "normal");
  const ContactFrame f = contact_frame(normal);
  const Eigen::Vector3d slip = centre_velocity + angular_velocity.cross(contact_point);
  Creepages c;
  c.longitudinal = slip.dot(f.t1) / forward_speed;
  c.lateral = slip.dot(f.t2) / forward_speed;
  c.spin = angular_velocity.dot(f.n) / forward_speed;
  return c;
}

}  // namespace wrc
