#include "core/geometry/contact_locus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {

ContactLocus::ContactLocus(const Profile& wheel, const PlacedRail& rail, const TrackParameters& track,
                           WheelSide side, const WheelsetPose& pose)
    : wheel_(wheel), rail_(rail), side_(side), pose_(pose), sigma_(side_sign(side)),
      taping_(track.taping_half_distance()), r0_(track.nominal_radius) {
  const double cpsi = std::cos(pose.yaw), spsi = std::sin(pose.yaw);
  const double cphi = std::cos(pose.roll), sphi = std::sin(pose.roll);
  // A = Rz(yaw) * Rx(roll)
  rotation_ << cpsi, -spsi * cphi, spsi * sphi,
               spsi, cpsi * cphi, -cpsi * sphi,
               0.0, sphi, cphi;
  const double a11 = rotation_(0, 0), a13 = rotation_(0, 2);
  a12_ = rotation_(0, 1);
  rho_ = std::hypot(a11, a13);
  beta_ = std::atan2(a13, a11);
  cos_beta_ = std::cos(beta_);
  sin_beta_ = std::sin(beta_);

  // Lateral track position of a body point at lateral coordinate yb is about y + yb*cos(roll):
  // invert for the rail's extent, with a margin that covers the radius term of roll and yaw.
  const double c = std::max(0.5, cphi * cpsi);
  const double margin = 0.002 + 1.2 * r0_ * (std::fabs(sphi) + std::fabs(spsi));
  double a = sigma_ * (rail.y_lower() - pose.y) / c - taping_;
  double b = sigma_ * (rail.y_upper() - pose.y) / c - taping_;
  if (a > b) std::swap(a, b);
  s_lower_ = std::max(wheel.lower(), a - margin);
  s_upper_ = std::min(wheel.upper(), b + margin);
  if (s_lower_ > s_upper_) s_lower_ = s_upper_ = wheel.lower();
}

LocusPoint ContactLocus::at(double s) const {
  LocusPoint p;
  s = std::clamp(s, wheel_.lower(), wheel_.upper());
  p.s = s;
  const ProfileSample f = wheel_.evaluate(s);
  const double radius = r0_ + f.height;
  // Normal in a cross-section plane: a11 sin(theta) + a13 cos(theta) = -sigma a12 R'(s).
  // theta = asin(q) - beta; its sine and cosine follow algebraically (no trigonometric calls).
  const double q = std::clamp(-sigma_ * a12_ * f.slope / rho_, -1.0, 1.0);
  const double cq = std::sqrt(std::max(1e-300, 1 - q * q));
  const double st = q * cos_beta_ - cq * sin_beta_, ct = cq * cos_beta_ + q * sin_beta_;
  const double dtheta = -sigma_ * a12_ * f.curvature / (rho_ * cq);
  const Eigen::Vector3d body(-radius * st, sigma_ * (taping_ + s), -radius * ct);
  const Eigen::Vector3d body_ds(-f.slope * st - radius * ct * dtheta, sigma_, -f.slope * ct + radius * st * dtheta);
  p.sin_theta = st;
  p.cos_theta = ct;
  p.radius = radius;
  p.wheel = rotation_ * body + Eigen::Vector3d(pose_.x, pose_.y, pose_.z);
  p.tangent = rotation_ * body_ds;
  p.rail = rail_.at(p.wheel.y());
  p.over_rail = p.rail.valid;
  if (p.over_rail) {
    p.distance = p.wheel.z() - p.rail.z;
    p.distance_slope = p.tangent.z() - p.rail.slope * p.tangent.y();
  }
  return p;
}

double ContactLocus::s_at_lateral(double y) const {
  // The locus point's lateral position is about y + sigma (taping + s): start there, then secant.
  double s0 = sigma_ * (y - pose_.y) - taping_;
  double f0 = at(s0).wheel.y() - y;
  double s1 = s0 - 1e-4, f1 = at(s1).wheel.y() - y;
  for (int i = 0; i < 8 && std::fabs(f1) > 1e-12 && f1 != f0; ++i) {
    const double s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    s0 = s1;
    f0 = f1;
    s1 = s2;
    f1 = at(s1).wheel.y() - y;
  }
  return s1;
}

double ContactLocus::distance_slope(double s) const {
  const LocusPoint p = at(s);
  return p.over_rail ? p.distance_slope : std::numeric_limits<double>::quiet_NaN();
}

Eigen::Vector3d ContactLocus::wheel_normal(const LocusPoint& p, double slope) const {
  const Eigen::Vector3d body(-p.sin_theta, -sigma_ * slope, -p.cos_theta);
  return (rotation_ * body).normalized();
}

}  // namespace wrc
