#include "core/models/contact_point_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/models/contact_model.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/one_point_model.hpp"

namespace wrc {
namespace {

enum Field {
  kS, kSRail, kTheta, kRx, kRy, kRz, kRailZ, kDistance0, kAngle, kRadius, kNx, kNy, kNz,
  kWheelLateral, kWheelRolling, kRailLateral, kRailRolling, kDistanceCurvature, kFieldCount
};

// Natural cubic spline on equally spaced nodes: second derivatives M with M_0 = M_{n-1} = 0 from
// M_{i-1} + 4 M_i + M_{i+1} = 6 (f_{i-1} - 2 f_i + f_{i+1}) / h^2 (Thomas algorithm).
void natural_spline(const double* f, double* m, int n, double h) {
  m[0] = m[n - 1] = 0.0;
  if (n < 3) return;
  std::vector<double> c(static_cast<size_t>(n), 0.0), d(static_cast<size_t>(n), 0.0);
  for (int i = 1; i < n - 1; ++i) {
    const double rhs = 6.0 * (f[i - 1] - 2.0 * f[i] + f[i + 1]) / (h * h);
    const double denom = 4.0 - (i > 1 ? c[i - 1] : 0.0);
    c[i] = 1.0 / denom;
    d[i] = (rhs - (i > 1 ? d[i - 1] : 0.0)) / denom;
  }
  m[n - 2] = d[n - 2];
  for (int i = n - 3; i >= 1; --i) m[i] = d[i] - c[i] * m[i + 1];
}

// Cell index and local coordinate of value on the grid [-half, half] with count nodes.
void locate(double value, int count, double half, const char* name, const char* unit, int& cell, double& t) {
  const double h = 2.0 * half / (count - 1);
  const double u = (value + half) / h;
  const double slack = 1e-9;
  if (!(u >= -slack && u <= (count - 1) + slack)) {
    std::ostringstream msg;
    msg << "interp: " << name << " = " << value << " " << unit << " is outside the interpolation table [" << -half
        << ", " << half << "] " << unit;
    throw OutsideModelError(msg.str());
  }
  cell = std::clamp(static_cast<int>(std::floor(u)), 0, count - 2);
  t = std::clamp(u - cell, 0.0, 1.0);
}

}  // namespace

static_assert(kFieldCount == 18, "ContactPointTable::kFields must match the field list");

ContactPointTable::ContactPointTable(const WheelsetGeometry& geometry, const InterpolationGrid& grid,
                                     const PotentialPointSearch& search)
    : grid_(grid) {
  grid_.validate();
  const double z_ref = geometry.track().nominal_radius;
  const double steepest = steepest_flange_point(geometry.wheel_profile());
  const size_t size = static_cast<size_t>(kFields) * grid_.roll_points * grid_.yaw_points * grid_.y_points;
  const double h_y = 2.0 * grid_.y_max / (grid_.y_points - 1);
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    std::vector<double>& v = values_[static_cast<int>(side)];
    std::vector<double>& m = second_[static_cast<int>(side)];
    v.assign(size, 0.0);
    m.assign(size, 0.0);
    for (int j = 0; j < grid_.roll_points; ++j) {
      for (int k = 0; k < grid_.yaw_points; ++k) {
        for (int i = 0; i < grid_.y_points; ++i) {
          WheelsetPose pose;
          pose.y = y_node(i);
          pose.z = z_ref;
          pose.roll = roll_node(j);
          pose.yaw = yaw_node(k);
          ContactPoint p;
          try {
            p = require_common_point(geometry, side, pose, search, steepest);
          } catch (const ContactConfigurationError& e) {
            throw ContactConfigurationError(std::string("interp table node: ") + e.what() +
                                            " (reduce the table's y_max, roll_max or yaw_max)");
          }
          const Eigen::Vector3d r = p.wheel_point - Eigen::Vector3d(pose.x, pose.y, pose.z);
          const double fields[kFields] = {p.s, p.s_rail, p.theta, r.x(), r.y(), r.z(), p.rail_point.z(),
                                          p.distance - z_ref, p.contact_angle, p.rolling_radius,
                                          p.normal.x(), p.normal.y(), p.normal.z(), p.wheel_curvature_lateral,
                                          p.wheel_curvature_rolling, p.rail_curvature_lateral,
                                          p.rail_curvature_rolling, p.distance_curvature};
          for (int f = 0; f < kFields; ++f) v[offset(f, j, k) + static_cast<size_t>(i)] = fields[f];
        }
        if (grid_.y_method == YInterpolation::kCubicSpline) {
          for (int f = 0; f < kFields; ++f)
            natural_spline(&v[offset(f, j, k)], &m[offset(f, j, k)], grid_.y_points, h_y);
        }
      }
    }
  }
}

ContactPoint ContactPointTable::at(WheelSide side, const WheelsetPose& pose) const {
  int iy, jr, kp;
  double ty, tr, tp;
  locate(pose.y, grid_.y_points, grid_.y_max, "y", "m", iy, ty);
  locate(pose.roll, grid_.roll_points, grid_.roll_max, "roll", "rad", jr, tr);
  locate(pose.yaw, grid_.yaw_points, grid_.yaw_max, "yaw", "rad", kp, tp);
  const std::vector<double>& v = values_[static_cast<int>(side)];
  const std::vector<double>& m = second_[static_cast<int>(side)];
  const bool spline = grid_.y_method == YInterpolation::kCubicSpline;
  const double h_y = 2.0 * grid_.y_max / (grid_.y_points - 1);
  // Spline weights of M_i and M_{i+1}: h^2/6 ((1-t)^3 - (1-t)) and h^2/6 (t^3 - t).
  const double s = 1.0 - ty;
  const double wm0 = h_y * h_y / 6.0 * (s * s * s - s), wm1 = h_y * h_y / 6.0 * (ty * ty * ty - ty);
  const double corner_weight[2][2] = {{(1 - tr) * (1 - tp), (1 - tr) * tp}, {tr * (1 - tp), tr * tp}};
  double out[kFields] = {};
  for (int dj = 0; dj < 2; ++dj) {
    for (int dk = 0; dk < 2; ++dk) {
      const double w = corner_weight[dj][dk];
      if (w == 0.0) continue;
      for (int f = 0; f < kFields; ++f) {
        const size_t o = offset(f, jr + dj, kp + dk) + static_cast<size_t>(iy);
        double value = s * v[o] + ty * v[o + 1];
        if (spline) value += wm0 * m[o] + wm1 * m[o + 1];
        out[f] += w * value;
      }
    }
  }
  ContactPoint p;
  p.side = side;
  p.s = out[kS];
  p.s_rail = out[kSRail];
  p.theta = out[kTheta];
  p.wheel_point = Eigen::Vector3d(pose.x + out[kRx], pose.y + out[kRy], pose.z + out[kRz]);
  p.rail_point = Eigen::Vector3d(p.wheel_point.x(), p.wheel_point.y(), out[kRailZ]);
  p.normal = Eigen::Vector3d(out[kNx], out[kNy], out[kNz]).normalized();
  p.distance = out[kDistance0] + pose.z;
  p.contact_angle = out[kAngle];
  p.rolling_radius = out[kRadius];
  p.wheel_curvature_lateral = out[kWheelLateral];
  p.wheel_curvature_rolling = out[kWheelRolling];
  p.rail_curvature_lateral = out[kRailLateral];
  p.rail_curvature_rolling = out[kRailRolling];
  p.distance_curvature = out[kDistanceCurvature];
  p.is_minimum = true;
  return p;
}

}  // namespace wrc
