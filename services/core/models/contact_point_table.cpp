// SPDX-License-Identifier: Apache-2.0
#include "core/models/contact_point_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/geometry/contact_point_fields.hpp"
#include "core/geometry/rigid_wheelset.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/models/flange_climb.hpp"
#include "core/models/one_point_model.hpp"
#include "core/models/wheel_constraint.hpp"

namespace wrc {
namespace {

// The table's fields: the contact point's (ContactPointField order), then the distance's two.
enum Field {
  kMonotoneFields = kContactPointFieldCount,  // the point's: monotone slopes in y, monotone Hermite in delta
  kDistance0 = kMonotoneFields,  // distance at z = 0: exact y slope, Hermite in delta with kDistanceRoll
  kDistanceRoll,              // d distance / droll (exact at the nodes): monotone slopes in y
  kFieldCount
};
constexpr int kMaxNodes = 9;  // roll_points and yaw_points (InterpolationGrid::validate())

// Monotone (Fritsch-Carlson) slopes of f sampled at equal spacing h: at an interior node the
// harmonic mean of the neighbouring secants (0 where they differ in sign), at the ends the
// three-point formula limited to keep the shape (Fritsch and Butland). Exact for quadratics
// away from extrema; no overshoot at a jump.
void monotone_slopes(const double* f, size_t stride, int n, double h, double* d) {
  auto secant = [&](int i) { return (f[(i + 1) * stride] - f[i * stride]) / h; };
  if (n == 2) {
    d[0] = d[stride] = secant(0);
    return;
  }
  for (int i = 1; i < n - 1; ++i) {
    const double a = secant(i - 1), b = secant(i);
    d[i * stride] = a * b > 0 ? 2.0 * a * b / (a + b) : 0.0;
  }
  auto end = [](double near, double far) {
    double s = 0.5 * (3.0 * near - far);
    if (s * near <= 0) return 0.0;
    if (near * far <= 0 && std::fabs(s) > 3.0 * std::fabs(near)) s = 3.0 * near;
    return s;
  };
  d[0] = end(secant(0), secant(1));
  d[(n - 1) * stride] = end(secant(n - 2), secant(n - 3));
}

// Cubic Hermite basis on a cell of length h at local t in [0, 1]: weights of f0, d0, f1, d1 for the
// value (w) and for the derivative along the cell (dw, per unit length).
struct HermiteBasis {
  double w[4];
  double dw[4];
  HermiteBasis(double t, double h) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 2 * t3 - 3 * t2 + 1;
    w[1] = (t3 - 2 * t2 + t) * h;
    w[2] = -2 * t3 + 3 * t2;
    w[3] = (t3 - t2) * h;
    dw[0] = (6 * t2 - 6 * t) / h;
    dw[1] = 3 * t2 - 4 * t + 1;
    dw[2] = (6 * t - 6 * t2) / h;
    dw[3] = 3 * t2 - 2 * t;
  }
  double value(double f0, double d0, double f1, double d1) const {
    return w[0] * f0 + w[1] * d0 + w[2] * f1 + w[3] * d1;
  }
  double derivative(double f0, double d0, double f1, double d1) const {
    return dw[0] * f0 + dw[1] * d0 + dw[2] * f1 + dw[3] * d1;
  }
};

[[noreturn]] void outside(const char* name, double value, const char* unit, double low, double high,
                          const char* what) {
  std::ostringstream msg;
  msg << "interp: " << name << " = " << value << " " << unit << " is outside the interpolation table [" << low << ", "
      << high << "] " << unit << what;
  throw OutsideModelError(msg.str());
}

// Cell index and local coordinate of value on the grid [-half, half] with count nodes.
void locate(double value, int count, double half, const char* name, const char* unit, int& cell, double& t) {
  const double h = 2.0 * half / (count - 1);
  const double u = (value + half) / h;
  const double slack = 1e-9;
  if (!(u >= -slack && u <= (count - 1) + slack)) outside(name, value, unit, -half, half, "");
  cell = std::clamp(static_cast<int>(std::floor(u)), 0, count - 2);
  t = std::clamp(u - cell, 0.0, 1.0);
}

// Lagrange weights L_k(x) and their derivatives through count equally spaced nodes on [-half, half].
void lagrange(double x, int count, double half, double* l, double* dl) {
  double nodes[kMaxNodes];
  for (int k = 0; k < count; ++k) nodes[k] = -half + 2.0 * half * k / (count - 1);
  for (int k = 0; k < count; ++k) {
    double value = 1.0, derivative = 0.0;
    for (int m = 0; m < count; ++m) {
      if (m == k) continue;
      const double denom = nodes[k] - nodes[m];
      derivative = derivative * (x - nodes[m]) / denom + value / denom;
      value *= (x - nodes[m]) / denom;
    }
    l[k] = value;
    dl[k] = derivative;
  }
}

// The same pose with another roll.
WheelsetPose with_roll(double y, double z, double roll, double yaw) {
  WheelsetPose p;
  p.y = y;
  p.z = z;
  p.roll = roll;
  p.yaw = yaw;
  return p;
}

}  // namespace

static_assert(kFieldCount == kContactPointFieldCount + 2, "ContactPointTable::kFields must match the field list");

ContactPointTable::ContactPointTable(const WheelsetGeometry& geometry, const InterpolationGrid& grid,
                                     const PotentialPointSearch& search)
    : grid_(grid) {
  grid_.validate();
  const double z_ref = geometry.track().nominal_radius;
  const double steepest = steepest_flange_point(geometry.wheel_profile());
  const int ny = grid_.y_points, nr = grid_.roll_points, nk = grid_.yaw_points;
  const double h_y = 2.0 * grid_.y_max / (ny - 1);
  RigidSolverOptions rigid_options;
  rigid_options.search = search;
  rigid_options.all_potential_points = false;
  const RigidWheelsetSolver solver(geometry, rigid_options);
  roll_.assign(static_cast<size_t>(nk) * static_cast<size_t>(ny) * 2, 0.0);
  for (auto& v : values_) v.assign(offset(nk, 0, 0), 0.0);
  for (int k = 0; k < nk; ++k) {
    const double yaw = yaw_node(k);
    RigidContact rigid;
    for (int i = 0; i < ny; ++i) {
      const double y = y_node(i);
      try {
        rigid = i == 0 ? solver.solve(y, yaw) : solver.solve(y, yaw, rigid);
      } catch (const std::runtime_error& e) {
        std::ostringstream msg;
        msg << "interp table node y = " << y << " m, yaw = " << yaw << " rad: " << e.what() << " (reduce y_max)";
        throw ContactConfigurationError(msg.str());
      }
      // Implicit differentiation of gap_L = gap_R = 0 at fixed yaw: dz + g_roll dphi = -g_y dy.
      const Eigen::Vector4d gl = vertical_gap_gradient(rigid.left(), rigid.pose);
      const Eigen::Vector4d gr = vertical_gap_gradient(rigid.right(), rigid.pose);
      const double roll_slope = -(gl[0] - gr[0]) / (gl[2] - gr[2]);
      roll_[index(k, i) * 2] = rigid.pose.roll;
      roll_[index(k, i) * 2 + 1] = roll_slope;
      for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
        std::vector<double>& v = values_[static_cast<int>(side)];
        for (int j = 0; j < nr; ++j) {
          const WheelsetPose pose = with_roll(y, z_ref, rigid.pose.roll + roll_offset(j), yaw);
          ContactPoint p;
          try {
            p = require_common_point(geometry, side, pose, search, steepest);
          } catch (const ContactConfigurationError& e) {
            throw ContactConfigurationError(std::string("interp table node: ") + e.what() +
                                            " (reduce the table's y_max, roll_band or yaw_max)");
          }
          const Eigen::Vector4d g = vertical_gap_gradient(p, pose);
          const ContactPointFields fields = contact_point_fields(p, pose);
          double* node = &v[offset(k, j, i)];
          std::copy(fields.begin(), fields.end(), node);
          node[kDistance0] = p.distance - z_ref;
          node[kDistanceRoll] = g[2];
          // The distance's exact slope along y at fixed delta (envelope gradient).
          node[kFields + kDistance0] = g[0] + g[2] * roll_slope;
        }
      }
    }
    for (auto& v : values_) {
      for (int j = 0; j < nr; ++j) {
        for (int f = 0; f < kFields; ++f) {
          if (f == kDistance0) continue;
          double* first = &v[offset(k, j, 0)];
          monotone_slopes(first + f, 2 * kFields, ny, h_y, first + kFields + f);
        }
      }
    }
  }
}

TableContact ContactPointTable::evaluate(WheelSide side, const WheelsetPose& pose) const {
  const int nr = grid_.roll_points, nk = grid_.yaw_points;
  int iy;
  double ty;
  locate(pose.y, grid_.y_points, grid_.y_max, "y", "m", iy, ty);
  if (!(std::fabs(pose.yaw) <= grid_.yaw_max * (1 + 1e-9)))
    outside("yaw", pose.yaw, "rad", -grid_.yaw_max, grid_.yaw_max, "");
  if (!(std::fabs(pose.roll) <= grid_.roll_max * (1 + 1e-9)))
    outside("roll", pose.roll, "rad", -grid_.roll_max, grid_.roll_max, " (InterpolationGrid::roll_max)");
  const double h_y = 2.0 * grid_.y_max / (grid_.y_points - 1);
  const HermiteBasis by(ty, h_y);
  double l[kMaxNodes], dl[kMaxNodes];
  lagrange(pose.yaw, nk, grid_.yaw_max, l, dl);

  // Rigid roll phi_r(y, yaw) and its partial derivatives.
  double roll_r = 0, roll_r_y = 0, roll_r_yaw = 0;
  for (int k = 0; k < nk; ++k) {
    const double* a = &roll_[index(k, iy) * 2];
    const double value = by.value(a[0], a[1], a[2], a[3]);
    roll_r += l[k] * value;
    roll_r_yaw += dl[k] * value;
    roll_r_y += l[k] * by.derivative(a[0], a[1], a[2], a[3]);
  }

  // Position in delta = roll - phi_r among the roll nodes; beyond the band the distance goes on
  // linearly from the edge node and the other fields are held there.
  const double delta = pose.roll - roll_r, band = grid_.roll_band, h_r = 2.0 * band / (nr - 1);
  const double u = std::clamp((delta + band) / h_r, 0.0, static_cast<double>(nr - 1));
  const int jr = std::min(static_cast<int>(std::floor(u)), nr - 2);
  const double tr = u - jr;
  const double beyond = delta - (-band + h_r * u);  // 0 inside the band
  const HermiteBasis br(tr, h_r);

  const std::vector<double>& v = values_[static_cast<int>(side)];
  ContactPointFields out{};
  double dist = 0, dist_delta = 0, dist_y = 0, dist_yaw = 0;
  for (int k = 0; k < nk; ++k) {
    // The y interpolants at every roll node of yaw node k (value; for the distance fields also d/dy).
    double f[kMaxNodes][kFields], fy[kMaxNodes][2];
    for (int j = 0; j < nr; ++j) {
      const double* n0 = &v[offset(k, j, iy)];
      const double* n1 = n0 + 2 * kFields;
      for (int q = 0; q < kFields; ++q) f[j][q] = by.value(n0[q], n0[kFields + q], n1[q], n1[kFields + q]);
      for (int q = 0; q < 2; ++q) {
        const int field = kDistance0 + q;
        fy[j][q] = by.derivative(n0[field], n0[kFields + field], n1[field], n1[kFields + field]);
      }
    }
    // Distance: Hermite in delta with the roll derivative as slope, linear beyond the band.
    const double* a = f[jr];
    const double* b = f[jr + 1];
    double value = br.value(a[kDistance0], a[kDistanceRoll], b[kDistance0], b[kDistanceRoll]);
    double d_delta = br.derivative(a[kDistance0], a[kDistanceRoll], b[kDistance0], b[kDistanceRoll]);
    double d_y = br.value(fy[jr][0], fy[jr][1], fy[jr + 1][0], fy[jr + 1][1]);
    if (beyond != 0.0) {
      value += d_delta * beyond;
      d_y += br.derivative(fy[jr][0], fy[jr][1], fy[jr + 1][0], fy[jr + 1][1]) * beyond;
    }
    dist += l[k] * value;
    dist_yaw += dl[k] * value;
    dist_delta += l[k] * d_delta;
    dist_y += l[k] * d_y;
    // The other fields: monotone Hermite in delta over the roll nodes.
    for (int q = 0; q < kMonotoneFields; ++q) {
      double column[kMaxNodes], slopes[kMaxNodes];
      for (int j = 0; j < nr; ++j) column[j] = f[j][q];
      monotone_slopes(column, 1, nr, h_r, slopes);
      out[q] += l[k] * br.value(column[jr], slopes[jr], column[jr + 1], slopes[jr + 1]);
    }
  }

  TableContact c;
  c.point = contact_point_from_fields(out, side, pose, dist + pose.z);
  // distance = z + D(y, roll - phi_r(y, yaw), yaw).
  c.gap_gradient = Eigen::Vector4d(dist_y - dist_delta * roll_r_y, 1.0, dist_delta, dist_yaw - dist_delta * roll_r_yaw);
  return c;
}

double ContactPointTable::rigid_roll(double y, double yaw) const {
  int iy;
  double ty;
  locate(y, grid_.y_points, grid_.y_max, "y", "m", iy, ty);
  if (!(std::fabs(yaw) <= grid_.yaw_max * (1 + 1e-9))) outside("yaw", yaw, "rad", -grid_.yaw_max, grid_.yaw_max, "");
  const HermiteBasis by(ty, 2.0 * grid_.y_max / (grid_.y_points - 1));
  double l[kMaxNodes], dl[kMaxNodes];
  lagrange(yaw, grid_.yaw_points, grid_.yaw_max, l, dl);
  double roll = 0;
  for (int k = 0; k < grid_.yaw_points; ++k) {
    const double* a = &roll_[index(k, iy) * 2];
    roll += l[k] * by.value(a[0], a[1], a[2], a[3]);
  }
  return roll;
}

double ContactPointTable::rigid_height(double y, double yaw) const {
  return -evaluate(WheelSide::kLeft, with_roll(y, 0.0, rigid_roll(y, yaw), yaw)).point.distance;
}

std::vector<double> ContactPointTable::data() const {
  std::vector<double> out{static_cast<double>(grid_.y_points), grid_.y_max,
                          static_cast<double>(grid_.roll_points), grid_.roll_band,
                          grid_.roll_max, static_cast<double>(grid_.yaw_points),
                          grid_.yaw_max};
  out.insert(out.end(), roll_.begin(), roll_.end());
  for (const auto& v : values_) out.insert(out.end(), v.begin(), v.end());
  return out;
}

}  // namespace wrc
