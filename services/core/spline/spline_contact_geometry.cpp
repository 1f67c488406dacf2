// SPDX-License-Identifier: Apache-2.0
#include "core/spline/spline_contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/contact/hertz.hpp"
#include "core/geometry/wheel_side.hpp"
#include "core/identity/sha256.hpp"
#include "core/model_interface/contact_model.hpp"
#include "core/model_interface/jump_transition.hpp"

namespace wrc {
namespace {

constexpr double kSlack = 1e-12;

// Tensor coordinates of a pose: (y, roll, yaw).
std::array<double, 3> coordinates(const WheelsetPose& pose) { return {pose.y, pose.roll, pose.yaw}; }

// The creep frame of a constraint: the rail's slope at the point is g = dz_touch/dy (envelope),
// normal (0, -g, 1) / sqrt(1 + g^2), contact angle atan(sign g), written into the fields evaluated.
void set_slope_frame(WheelSide side, double g, std::array<double, kSplineFieldCount>& value, int value_count) {
  const double n = 1.0 / std::sqrt(1.0 + g * g);
  if (value_count > kFieldContactAngle) value[kFieldContactAngle] = std::atan(side_sign(side) * g);
  if (value_count > kFieldNormalZ) {
    value[kFieldNormalX] = 0.0;
    value[kFieldNormalY] = -g * n;
    value[kFieldNormalZ] = n;
  }
}

}  // namespace

void JumpSurface::evaluate(double roll, double yaw, double& value, double* gradient, double* hessian) const {
  const double r[3] = {1.0, roll, roll * roll}, dr[3] = {0.0, 1.0, 2.0 * roll};
  const double p[3] = {1.0, yaw, yaw * yaw}, dp[3] = {0.0, 1.0, 2.0 * yaw};
  value = 0.0;
  double g0 = 0, g1 = 0, h00 = 0, h01 = 0, h11 = 0;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double k = c[static_cast<size_t>(3 * a + b)];
      value += k * r[a] * p[b];
      g0 += k * dr[a] * p[b];
      g1 += k * r[a] * dp[b];
      h00 += a == 2 ? 2.0 * k * p[b] : 0.0;
      h01 += k * dr[a] * dp[b];
      h11 += b == 2 ? 2.0 * k * r[a] : 0.0;
    }
  }
  if (gradient) gradient[0] = g0, gradient[1] = g1;
  if (hessian) hessian[0] = h00, hessian[1] = h01, hessian[2] = h11;
}

SplineContactGeometry::SplineContactGeometry(std::array<SplineWheel, 2> wheels, SplineBox left_box, double s_split,
                                             double lateral_curvature_floor)
    : wheels_(std::move(wheels)), left_box_(left_box), s_split_(s_split),
      lateral_curvature_floor_(lateral_curvature_floor) {
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const SplineWheel& w = wheel(side);
    if (w.branches.empty() || w.jumps.size() + 1 != w.branches.size())
      throw std::invalid_argument(std::string("spline geometry: the ") + side_name(side) + " wheel has " +
                                  std::to_string(w.branches.size()) + " branches and " +
                                  std::to_string(w.jumps.size()) + " jumps; expected one branch more than jumps");
    for (size_t m = 0; m < w.jumps.size(); ++m) {
      const JumpSurface& j = w.jumps[m];
      if (!(j.height_half_width > 0.0 && std::isfinite(j.height_half_width) && j.y_reach > 0.0 &&
            std::isfinite(j.y_reach))) {
        std::ostringstream msg;
        msg << "spline geometry: the " << side_name(side) << " wheel's jump " << m << " has height_half_width = "
            << j.height_half_width << " m and y_reach = " << j.y_reach << " m; both must be positive and finite";
        throw std::invalid_argument(msg.str());
      }
    }
    const SplineBox b = box(side);
    const double lo[3] = {b.y_min, -b.roll_max, -b.yaw_max}, hi[3] = {b.y_max, b.roll_max, b.yaw_max};
    double y_lower = std::numeric_limits<double>::infinity(), y_upper = -y_lower;
    for (const TensorSplineSet& set : w.branches) {
      if (set.basis().dimension() != 3 || set.functions() != kSplineFieldCount) {
        throw std::invalid_argument(std::string("spline geometry: the ") + side_name(side) + " wheel has " +
                                    std::to_string(set.functions()) + " functions over " +
                                    std::to_string(set.basis().dimension()) + " variables; expected " +
                                    std::to_string(kSplineFieldCount) + " over (y, roll, yaw)");
      }
      y_lower = std::min(y_lower, set.basis().basis(0).lower());
      y_upper = std::max(y_upper, set.basis().basis(0).upper());
      for (int k = 0; k < 3; ++k) {
        const BSplineBasis& basis = set.basis().basis(k);
        const double l = k == 0 ? y_lower : basis.lower(), u = k == 0 ? y_upper : basis.upper();
        if (k > 0 && (l > lo[k] + kSlack || u < hi[k] - kSlack)) {
          std::ostringstream msg;
          msg << "spline geometry: the " << side_name(side) << " wheel's basis in variable " << k << " covers [" << l
              << ", " << u << "], not the box [" << lo[k] << ", " << hi[k] << "]";
          throw std::invalid_argument(msg.str());
        }
      }
    }
    if (y_lower > lo[0] + kSlack || y_upper < hi[0] - kSlack) {
      std::ostringstream msg;
      msg << "spline geometry: the " << side_name(side) << " wheel's bases in variable 0 cover [" << y_lower << ", "
          << y_upper << "], not the box [" << lo[0] << ", " << hi[0] << "]";
      throw std::invalid_argument(msg.str());
    }
  }
}

SplineBox SplineContactGeometry::box(WheelSide side) const {
  if (side == WheelSide::kLeft) return left_box_;
  return left_box_.mirrored();
}

bool SplineContactGeometry::inside(WheelSide side, const WheelsetPose& pose) const {
  const SplineBox b = box(side);
  return pose.y >= b.y_min - kSlack && pose.y <= b.y_max + kSlack && std::abs(pose.roll) <= b.roll_max + kSlack &&
         std::abs(pose.yaw) <= b.yaw_max + kSlack;
}

std::string SplineContactGeometry::outside_reason(WheelSide side, const WheelsetPose& pose) const {
  const SplineBox b = box(side);
  std::ostringstream msg;
  msg << "the " << side_name(side) << " wheel's configuration is outside the spline model's box: ";
  if (!(pose.y >= b.y_min - kSlack && pose.y <= b.y_max + kSlack)) {
    msg << "y = " << pose.y << " m not in [" << b.y_min << ", " << b.y_max << "] m";
  } else if (!(std::abs(pose.roll) <= b.roll_max + kSlack)) {
    msg << "roll = " << pose.roll << " rad not in [" << -b.roll_max << ", " << b.roll_max << "] rad";
  } else if (!(std::abs(pose.yaw) <= b.yaw_max + kSlack)) {
    msg << "yaw = " << pose.yaw << " rad not in [" << -b.yaw_max << ", " << b.yaw_max << "] rad";
  } else {
    return "";
  }
  return msg.str();
}

void SplineContactGeometry::evaluate(WheelSide side, const WheelsetPose& pose, SplineDerivatives derivatives,
                                     SplineEvaluation& out, int value_count, int derivative_fields) const {
  if (derivative_fields < 1 || derivative_fields > 2)
    throw std::invalid_argument("SplineContactGeometry::evaluate: derivative_fields = " +
                                std::to_string(derivative_fields) + " is not 1 (z) or 2 (z and the flange clearance)");
  const std::array<double, 3> x = coordinates(pose);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  value_count = std::clamp(value_count, 0, static_cast<int>(kSplineFieldCount));
  for (int j = value_count; j < kSplineFieldCount; ++j) out.value[static_cast<size_t>(j)] = kNaN;
  const SplineWheel& w = wheel(side);
  // z and the flange clearance are fields 0 and 1: their derivatives come from one query.
  static_assert(kFieldZ == 0 && kFieldFlangeClearance == 1, "the derivative fields lead the list");
  const int derivative_count = derivatives == SplineDerivatives::kValue ? 0 : derivative_fields;
  // The pose's branch by the jump surfaces, and the first jump within whose y reach it lies.
  size_t branch = 0, near = w.jumps.size();
  for (size_t m = 0; m < w.jumps.size(); ++m) {
    const double v = w.jumps[m].at(pose.roll, pose.yaw);
    if (pose.y >= v) branch = m + 1;
    if (near == w.jumps.size() && std::abs(pose.y - v) < w.jumps[m].y_reach) near = m;
  }
  double d[20];
  out.upper_share = out.lower_slope = out.upper_slope = kNaN;
  if (near == w.jumps.size()) {
    w.branches[branch].query(x.data(), value_count, out.value.data(), derivative_count, d);
  } else {
    // Smooth maximum of the two branches' touching heights z_a (below the jump) and z_b (above):
    // with d = z_b - z_a, h the jump's height half-width and u = (1 + d / h) / 2 in [0, 1],
    // z = z_a + h phi(d / h), phi(t) = 2 (u^6 - 3 u^5 + 5/2 u^4), phi' = w(u) = u^3 (10 - 15 u +
    // 6 u^2), phi'' = w'(u) / 2; outside |d| < h simply the higher branch. grad z = (1 - w) grad
    // z_a + w grad z_b, H z = (1 - w) H z_a + w H z_b + w'(u) / (2 h) grad d grad d^T. Every other
    // field f (the clearance included) is f_a + w (f_b - f_a), its gradient gaining (f_b - f_a)
    // w'(u) / (2 h) grad d.
    std::array<double, kSplineFieldCount> va, vb;
    double da[20], db[20];
    const int need = std::max(value_count, 1);
    w.branches[near].query(x.data(), need, va.data(), derivative_count, da);
    w.branches[near + 1].query(x.data(), need, vb.data(), derivative_count, db);
    const SmoothMaximum blend = smooth_maximum(va[kFieldZ], vb[kFieldZ], w.jumps[near].height_half_width);
    const double s = blend.share;
    const double s1 = blend.share_slope;  // dw/dd = w'(u) / (2 h)
    for (int j = 0; j < value_count; ++j)
      out.value[static_cast<size_t>(j)] = va[static_cast<size_t>(j)] + s * (vb[static_cast<size_t>(j)] - va[static_cast<size_t>(j)]);
    // z itself: the smooth maximum, z_a + h phi(d / h) (z_a or z_b outside the band).
    if (value_count > kFieldZ) out.value[kFieldZ] = blend.value;
    if (s > 0.0 && s < 1.0) {
      out.upper_share = s;
      out.lower_value = va;
      out.upper_value = vb;
      if (derivative_count > 0) {
        out.lower_slope = da[1];
        out.upper_slope = db[1];
        set_slope_frame(side, da[1], out.lower_value, value_count);
        set_slope_frame(side, db[1], out.upper_value, value_count);
      }
    }
    if (derivative_count > 0) {
      // grad d and its Hessian-free use: slot order of a field's 10 derivatives: value, 3
      // gradient components, 6 Hessian entries (yy, y roll, y yaw, roll roll, roll yaw, yaw yaw).
      double gd[3];
      for (int k = 0; k < 3; ++k) gd[k] = db[1 + k] - da[1 + k];
      static constexpr int kRow[6] = {0, 0, 0, 1, 1, 2}, kCol[6] = {0, 1, 2, 1, 2, 2};
      for (int f = 0; f < derivative_count; ++f) {
        const double* a = da + 10 * f;
        const double* b = db + 10 * f;
        double* o = d + 10 * f;
        o[0] = f == 0 ? blend.value : a[0] + s * (b[0] - a[0]);
        // z (f = 0): no (f_b - f_a) term in its gradient, the curvature term in its Hessian; the
        // clearance (f = 1): the share's gradient term, its Hessian is not used (NaN).
        const double diff = f == 0 ? 0.0 : b[0] - a[0];
        for (int k = 0; k < 3; ++k) o[1 + k] = a[1 + k] + s * (b[1 + k] - a[1 + k]) + diff * s1 * gd[k];
        for (int q = 0; q < 6; ++q) {
          const int k = kRow[q], l = kCol[q];
          o[4 + q] = f == 0 ? a[4 + q] + s * (b[4 + q] - a[4 + q]) + s1 * gd[k] * gd[l]
                            : std::numeric_limits<double>::quiet_NaN();
        }
      }
    }
  }
  if (derivative_count == 0) return;
  std::copy(d + 1, d + 4, out.z_gradient.begin());
  std::copy(d + 4, d + 10, out.z_hessian.begin());
  if (derivative_fields == 2) {
    std::copy(d + 11, d + 14, out.clearance_gradient.begin());
  } else {
    out.clearance_gradient.fill(kNaN);
  }
  set_slope_frame(side, out.z_gradient[0], out.value, value_count);
}

ContactPoint SplineContactGeometry::contact_point(WheelSide side, const WheelsetPose& pose,
                                                  const SplineEvaluation& e) const {
  ContactPointFields fields;
  for (int k = 0; k < kContactPointFieldCount; ++k)
    fields[static_cast<size_t>(k)] = e.value[kSplineFieldOfPointField[static_cast<size_t>(k)]];
  // The rail point lies vertically below the wheel point; its fitted height is that at z_touch.
  return contact_point_from_fields(fields, side, pose, pose.z - e.value[kFieldZ]);
}

PatchShape SplineContactGeometry::patch_shape(const SplineEvaluation& e) const {
  const auto& v = e.value;
  PatchShape out;
  HertzShape& s = out.shape;
  s.A = v[kFieldHertzA];
  s.B = v[kFieldHertzB];
  s.minor_over_major = v[kFieldMinorOverMajor];
  s.eccentricity = std::sqrt(std::max(0.0, (1.0 - s.minor_over_major) * (1.0 + s.minor_over_major)));
  s.K = v[kFieldEllipticK];
  s.E = v[kFieldEllipticE];
  s.m = v[kFieldHertzM];
  s.n = v[kFieldHertzN];
  s.axis_ratio = s.m / s.n;
  const double raw_b = 0.5 * (v[kFieldWheelCurvatureLateral] + v[kFieldRailCurvatureLateral]);
  out.floored = !(raw_b > lateral_curvature_floor_ * s.A);
  // Where the fit reaches past its samples' smooth stretches (a box over flange contact, where the
  // lateral curvature jumps) it can overshoot into a shape no Hertz ellipse has (B <= 0): the
  // shape is then the exact one of the fitted curvatures, B floored as the exact models floor it
  // (patch_builder.hpp). Within the samples' reach the fitted shape stands as fitted.
  const bool valid = s.A > 0.0 && s.B > 0.0 && s.minor_over_major > 0.0 && s.minor_over_major <= 1.0 && s.K > 0.0 &&
                     s.E > 0.0 && s.m > 0.0 && s.n > 0.0;
  if (!valid) {
    try {
      s = hertz_shape(s.A, std::max(s.B, lateral_curvature_floor_ * s.A));
    } catch (const std::invalid_argument& no_ellipse) {
      throw ContactConfigurationError(std::string("spline model: no Hertz ellipse for the fitted curvatures: ") +
                                      no_ellipse.what());
    }
    out.floored = true;
  }
  return out;
}

std::string SplineContactGeometry::data_hash() const {
  static_assert(sizeof(double) == 8, "model data are hashed as IEEE doubles");
  std::vector<double> data;
  for (const SplineWheel& w : wheels_) {
    for (const JumpSurface& j : w.jumps) {
      data.insert(data.end(), j.c.begin(), j.c.end());
      data.push_back(j.height_half_width);
      data.push_back(j.y_reach);
    }
    for (const TensorSplineSet& set : w.branches) {
      for (const BSplineBasis& b : set.basis().bases()) {
        data.push_back(b.degree());
        data.insert(data.end(), b.breakpoints().begin(), b.breakpoints().end());
      }
      const Eigen::MatrixXd c = set.coefficients();
      for (Eigen::Index j = 0; j < c.cols(); ++j)
        for (Eigen::Index i = 0; i < c.rows(); ++i) data.push_back(c(i, j));
    }
  }
  return sha256_hex_of_doubles(data);
}

}  // namespace wrc
