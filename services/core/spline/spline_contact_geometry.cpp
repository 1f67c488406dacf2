#include "core/spline/spline_contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/geometry/wheel_side.hpp"
#include "core/identity/sha256.hpp"

namespace wrc {
namespace {

constexpr double kSlack = 1e-12;

// Tensor coordinates of a pose: (y, roll, yaw).
std::array<double, 3> coordinates(const WheelsetPose& pose) { return {pose.y, pose.roll, pose.yaw}; }

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
                                             double lateral_curvature_floor, double transition)
    : wheels_(std::move(wheels)), left_box_(left_box), s_split_(s_split),
      lateral_curvature_floor_(lateral_curvature_floor), transition_(transition) {
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const SplineWheel& w = wheel(side);
    if (w.branches.empty() || w.jumps.size() + 1 != w.branches.size())
      throw std::invalid_argument(std::string("spline geometry: the ") + side_name(side) + " wheel has " +
                                  std::to_string(w.branches.size()) + " branches and " +
                                  std::to_string(w.jumps.size()) + " jumps; expected one branch more than jumps");
    if (!w.jumps.empty() && !(transition_ > 0.0))
      throw std::invalid_argument("spline geometry: branches need a transition > 0");
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
  // The pose's branch, and the jump whose transition it lies in (if any).
  size_t branch = 0, blend = w.jumps.size();
  double jump_y = 0;
  for (size_t m = 0; m < w.jumps.size(); ++m) {
    const double v = w.jumps[m].at(pose.roll, pose.yaw);
    if (pose.y >= v) branch = m + 1;
    if (blend == w.jumps.size() && std::abs(pose.y - v) < transition_) blend = m, jump_y = v;
  }
  // z and the flange clearance are fields 0 and 1: their derivatives come from one query.
  static_assert(kFieldZ == 0 && kFieldFlangeClearance == 1, "the derivative fields lead the list");
  const int derivative_count = derivatives == SplineDerivatives::kValue ? 0 : derivative_fields;
  double d[20];
  if (blend == w.jumps.size()) {
    w.branches[branch].query(x.data(), value_count, out.value.data(), derivative_count, d);
  } else {
    // C2 step between the branch below (a) and above (b) the jump: w(u) = u^3 (10 - 15 u + 6 u^2),
    // u = (1 + t) / 2, t = (y - y_jump(roll, yaw)) / transition.
    std::array<double, kSplineFieldCount> va, vb;
    double da[20], db[20];
    w.branches[blend].query(x.data(), value_count, va.data(), derivative_count, da);
    w.branches[blend + 1].query(x.data(), value_count, vb.data(), derivative_count, db);
    const double t = (pose.y - jump_y) / transition_, u = 0.5 * (1.0 + t);
    const double s = u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
    for (int j = 0; j < value_count; ++j)
      out.value[static_cast<size_t>(j)] = va[static_cast<size_t>(j)] + s * (vb[static_cast<size_t>(j)] - va[static_cast<size_t>(j)]);
    if (derivative_count > 0) {
      double jump_gradient[2], jump_hessian[3];
      w.jumps[blend].evaluate(pose.roll, pose.yaw, jump_y, jump_gradient, jump_hessian);
      const double s1 = 15.0 * u * u * (1.0 - u) * (1.0 - u) / transition_;                    // dw/dy'
      const double s2 = 15.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / (transition_ * transition_);  // d2w/dy'2
      // y' = y - y_jump: its gradient and Hessian (slot order yy, y roll, y yaw, roll roll, roll yaw, yaw yaw).
      const double gt[3] = {1.0, -jump_gradient[0], -jump_gradient[1]};
      const double ht[6] = {0, 0, 0, -jump_hessian[0], -jump_hessian[1], -jump_hessian[2]};
      static constexpr int kRow[6] = {0, 0, 0, 1, 1, 2}, kCol[6] = {0, 1, 2, 1, 2, 2};
      for (int f = 0; f < derivative_count; ++f) {
        const double* a = da + 10 * f;
        const double* b = db + 10 * f;
        double* o = d + 10 * f;
        const double diff = b[0] - a[0];
        o[0] = a[0] + s * diff;
        for (int k = 0; k < 3; ++k) o[1 + k] = a[1 + k] + s * (b[1 + k] - a[1 + k]) + diff * s1 * gt[k];
        for (int q = 0; q < 6; ++q) {
          const int k = kRow[q], l = kCol[q];
          o[4 + q] = a[4 + q] + s * (b[4 + q] - a[4 + q]) + s1 * gt[k] * (b[1 + l] - a[1 + l]) +
                     s1 * gt[l] * (b[1 + k] - a[1 + k]) + diff * (s2 * gt[k] * gt[l] + s1 * ht[q]);
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
  // The creep frame of the constraint: the rail's slope at the point is dz_touch/dy (envelope).
  const double g = out.z_gradient[0], n = 1.0 / std::sqrt(1.0 + g * g);
  if (value_count > kFieldContactAngle) out.value[kFieldContactAngle] = std::atan(side_sign(side) * g);
  if (value_count > kFieldNormalZ) {
    out.value[kFieldNormalX] = 0.0;
    out.value[kFieldNormalY] = -g * n;
    out.value[kFieldNormalZ] = n;
  }
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
  return out;
}

std::string SplineContactGeometry::data_hash() const {
  static_assert(sizeof(double) == 8, "model data are hashed as IEEE doubles");
  std::vector<double> data{transition_};
  for (const SplineWheel& w : wheels_) {
    for (const JumpSurface& j : w.jumps) data.insert(data.end(), j.c.begin(), j.c.end());
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
