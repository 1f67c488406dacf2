// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/track_frames.hpp"
#include "core/vehicle/rotations.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace wrc {
namespace {

// 8-point Gauss-Legendre on [-1, 1]: nodes +-x_i with weights w_i. Exact for polynomials of degree
// 15; on a part of h <= 20 m where the heading is a quadratic with |kappa| <= 1/50 m, the error of
// int cos(theta) is h^17 (8!)^4 / (17 (16!)^3) max|d^16 cos(theta)/du^16| <= 20 (0.4)^16 1.7e-24,
// far below rounding.
constexpr std::array<double, 4> kNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                       0.9602898564975363};
constexpr std::array<double, 4> kWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                         0.1012285362903763};
constexpr double kLongestPart = 20.0;  // [m]

// The distances where the curvature and cant may change slope: 0 and every segment's end, summed
// as TrackLayout sums them.
std::vector<double> breakpoints(const TrackLayout& layout) {
  std::vector<double> b{0.0};
  double s = 0.0;
  for (const TrackSegment& seg : layout.segments()) {
    s += seg.length;
    b.push_back(s);
  }
  return b;
}

// The pieces from s0 to s (either order) on which the curvature is linear.
std::vector<double> pieces(const TrackLayout& layout, double s0, double s) {
  std::vector<double> cuts{s0};
  const double lo = std::min(s0, s), hi = std::max(s0, s);
  std::vector<double> inner;
  for (double b : breakpoints(layout))
    if (b > lo && b < hi) inner.push_back(b);
  if (s < s0) std::reverse(inner.begin(), inner.end());
  cuts.insert(cuts.end(), inner.begin(), inner.end());
  cuts.push_back(s);
  return cuts;
}

struct Plan {
  double heading = 0;  // [rad] from s0 to s
  double x = 0, y = 0;  // [m] the centre line at s in the plan axes of s0
};

Plan plan(const TrackLayout& layout, double s0, double s, bool with_position) {
  Plan p;
  if (s == s0) return p;
  const std::vector<double> cuts = pieces(layout, s0, s);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double u0 = cuts[k], u1 = cuts[k + 1];
    const double h = u1 - u0;  // signed
    const double kappa0 = layout.at(u0).curvature;
    const double kappa1 = layout.at(u1).curvature;  // continuous, so the piece's end value
    const double slope = (kappa1 - kappa0) / h;
    if (with_position) {
      const int parts = std::max(1, static_cast<int>(std::ceil(std::abs(h) / kLongestPart)));
      const double step = h / parts;
      for (int j = 0; j < parts; ++j) {
        const double t0 = j * step;  // from u0
        double c = 0.0, sn = 0.0;
        for (std::size_t i = 0; i < kNodes.size(); ++i) {
          for (double sign : {-1.0, 1.0}) {
            const double t = t0 + 0.5 * step * (1.0 + sign * kNodes[i]);
            const double theta = p.heading + kappa0 * t + 0.5 * slope * t * t;
            c += kWeights[i] * std::cos(theta);
            sn += kWeights[i] * std::sin(theta);
          }
        }
        p.x += 0.5 * step * c;
        p.y += 0.5 * step * sn;
      }
    }
    p.heading += 0.5 * h * (kappa0 + kappa1);
  }
  return p;
}

}  // namespace

double track_heading_change(const TrackLayout& layout, double s0, double s) {
  return plan(layout, s0, s, false).heading;
}

FramePose track_frame_pose(const TrackLayout& layout, double s0, double s) {
  FramePose pose;
  if (s == s0) return pose;
  const Plan p = plan(layout, s0, s, true);
  const Eigen::Matrix3d back = rotation_x(-layout.at(s0).cant_angle);
  pose.rotation = back * rotation_z(p.heading) * rotation_x(layout.at(s).cant_angle);
  pose.translation = back * Eigen::Vector3d(p.x, p.y, 0.0);
  return pose;
}

TrackFrameTwist track_frame_twist(const TrackLayout& layout, double s) {
  const TrackPoint t = layout.at(s);
  TrackFrameTwist twist;
  const double cant_rate = s < 0.0 ? 0.0 : t.cant_angle_rate;
  twist.angular = Eigen::Vector3d(cant_rate, t.curvature * std::sin(t.cant_angle), t.curvature * std::cos(t.cant_angle));
  return twist;
}

}  // namespace wrc
