// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/contact_locus.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wrc {

ContactLocus::ContactLocus(const Profile& wheel, const PlacedRail& rail, const TrackParameters& track,
                           WheelSide side, const WheelsetPose& pose, const SlopeEnvelope* wheel_envelope)
    : wheel_(wheel), rail_(rail), wheel_envelope_(wheel_envelope), side_(side), pose_(pose), sigma_(side_sign(side)),
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
  abs_sin_roll_ = std::fabs(sphi);
  abs_sin_yaw_ = std::fabs(spsi);
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
  const double dtheta = -sigma_ * a12_ * f.second_derivative / (rho_ * cq);
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

double ContactLocus::distance_curvature_bound(double s0, double s1) const {
  if (!wheel_envelope_ || wheel_envelope_->empty()) return 0.0;
  // distance'' = W_z'' - z_r'' (W_y')^2 - z_r' W_y'' along C. Without yaw, W_z'' = -F'' cos(roll),
  // W_y' = sigma cos(roll) + F' sin(roll), W_y'' = F'' sin(roll): the wheel and rail curvature terms
  // are bounded together by interval arithmetic (on a conformal tread they nearly cancel), the
  // roll coupling and the yaw terms (theta' ~ sin(yaw) F'': r0 theta'^2 and |F'| theta') by magnitudes.
  const double sr = abs_sin_roll_, sy = abs_sin_yaw_, cr = std::sqrt(std::max(0.0, 1 - sr * sr));
  double w2lo, w2hi;
  wheel_envelope_->second_range(s0, s1, w2lo, w2hi);
  const double rp = wheel_envelope_->max_slope(s0, s1);
  const double rpp = std::max(std::fabs(w2lo), std::fabs(w2hi));
  const double y0 = pose_.y + sigma_ * (taping_ + s0), y1 = pose_.y + sigma_ * (taping_ + s1);
  const double pad = 1e-3 + r0_ * (sr + sy);
  const double ya = std::min(y0, y1) - pad, yb = std::max(y0, y1) + pad;
  double z2lo, z2hi;
  rail_.envelope().second_range(ya, yb, z2lo, z2hi);
  const double zp = rail_.envelope().max_slope(ya, yb);
  const double theta_rate = sy * rpp * 1.1;
  const double wy_lo = std::max(0.0, cr - rp * sr - r0_ * theta_rate * sy), wy_hi = cr + rp * sr + r0_ * theta_rate * sy;
  const double w_lo = wy_lo * wy_lo, w_hi = wy_hi * wy_hi;
  // -F'' cos(roll) - z_r'' w with F'' in [w2lo, w2hi], z_r'' in [z2lo, z2hi], w in [w_lo, w_hi].
  const double products[4] = {z2lo * w_lo, z2lo * w_hi, z2hi * w_lo, z2hi * w_hi};
  const double rail_lo = *std::min_element(products, products + 4), rail_hi = *std::max_element(products, products + 4);
  const double lo = -w2hi * cr - rail_hi, hi = -w2lo * cr - rail_lo;
  const double coupled = std::max(std::fabs(lo), std::fabs(hi));
  return coupled + zp * rpp * sr + 2 * (r0_ * theta_rate * theta_rate + rp * theta_rate) + 1.0;
}

ContactLocus::LeanPoint ContactLocus::lean_at(double s) const {
  // at() without the x components, the 3-D vectors and the rail lookup.
  s = std::clamp(s, wheel_.lower(), wheel_.upper());
  const ProfileSample f = wheel_.evaluate(s);
  const double radius = r0_ + f.height;
  double st = -sin_beta_, ct = cos_beta_, dtheta = 0.0;  // without yaw (a12 = 0) theta is constant
  if (a12_ != 0.0) {
    const double q = std::clamp(-sigma_ * a12_ * f.slope / rho_, -1.0, 1.0);
    const double cq = std::sqrt(std::max(1e-300, 1 - q * q));
    st = q * cos_beta_ - cq * sin_beta_;
    ct = cq * cos_beta_ + q * sin_beta_;
    dtheta = -sigma_ * a12_ * f.second_derivative / (rho_ * cq);
  }
  const double bx = -radius * st, by = sigma_ * (taping_ + s), bz = -radius * ct;
  const double dx = -f.slope * st - radius * ct * dtheta, dy = sigma_, dz = -f.slope * ct + radius * st * dtheta;
  LeanPoint p;
  p.y = rotation_(1, 0) * bx + rotation_(1, 1) * by + rotation_(1, 2) * bz + pose_.y;
  p.z = rotation_(2, 0) * bx + rotation_(2, 1) * by + rotation_(2, 2) * bz + pose_.z;
  p.dy = rotation_(1, 0) * dx + rotation_(1, 1) * dy + rotation_(1, 2) * dz;
  p.dz = rotation_(2, 0) * dx + rotation_(2, 1) * dy + rotation_(2, 2) * dz;
  return p;
}

double ContactLocus::lateral_at(double s) const { return lean_at(s).y; }

double ContactLocus::s_at_lateral(double y) const {
  // The locus point's lateral position is about y + sigma (taping + s): start there, then secant.
  double s0 = sigma_ * (y - pose_.y) - taping_;
  double f0 = lateral_at(s0) - y;
  double s1 = s0 - 1e-4, f1 = lateral_at(s1) - y;
  for (int i = 0; i < 8 && std::fabs(f1) > 1e-12 && f1 != f0; ++i) {
    const double s2 = s1 - f1 * (s1 - s0) / (f1 - f0);
    s0 = s1;
    f0 = f1;
    s1 = s2;
    f1 = lateral_at(s1) - y;
  }
  return s1;
}

void ContactLocus::distance_and_slope(double s, double& distance, double& slope) const {
  const LeanPoint p = lean_at(s);
  double rail_z, rail_slope;
  if (!rail_.height_and_slope_at(p.y, rail_z, rail_slope)) {
    distance = slope = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  distance = p.z - rail_z;
  slope = p.dz - rail_slope * p.dy;
}

double ContactLocus::distance_slope(double s) const {
  double distance, slope;
  distance_and_slope(s, distance, slope);
  return slope;
}

Eigen::Vector3d ContactLocus::wheel_normal(const LocusPoint& p, double slope) const {
  const Eigen::Vector3d body(-p.sin_theta, -sigma_ * slope, -p.cos_theta);
  return (rotation_ * body).normalized();
}

}  // namespace wrc
