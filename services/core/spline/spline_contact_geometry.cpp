#include "core/spline/spline_contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/identity/sha256.hpp"

namespace wrc {
namespace {

constexpr double kSlack = 1e-12;

// Tensor coordinates of a pose: (y, roll, yaw).
std::array<double, 3> coordinates(const WheelsetPose& pose) { return {pose.y, pose.roll, pose.yaw}; }

}  // namespace

SplineContactGeometry::SplineContactGeometry(std::vector<TensorSplineSet> wheels, SplineBox left_box, double s_split,
                                             double lateral_curvature_floor)
    : wheels_(std::move(wheels)), left_box_(left_box), s_split_(s_split),
      lateral_curvature_floor_(lateral_curvature_floor) {
  if (wheels_.size() != 2) throw std::invalid_argument("spline geometry: needs the splines of 2 wheels");
  for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) {
    const TensorSplineSet& set = wheel(side);
    if (set.basis().dimension() != 3 || set.functions() != kSplineFieldCount) {
      throw std::invalid_argument(std::string("spline geometry: the ") + side_name(side) + " wheel has " +
                                  std::to_string(set.functions()) + " functions over " +
                                  std::to_string(set.basis().dimension()) + " variables; expected " +
                                  std::to_string(kSplineFieldCount) + " over (y, roll, yaw)");
    }
    const SplineBox b = box(side);
    const double lo[3] = {b.y_min, -b.roll_max, -b.yaw_max}, hi[3] = {b.y_max, b.roll_max, b.yaw_max};
    for (int k = 0; k < 3; ++k) {
      const BSplineBasis& basis = set.basis().basis(k);
      if (basis.lower() > lo[k] + kSlack || basis.upper() < hi[k] - kSlack) {
        std::ostringstream msg;
        msg << "spline geometry: the " << side_name(side) << " wheel's basis in variable " << k << " covers ["
            << basis.lower() << ", " << basis.upper() << "], not the box [" << lo[k] << ", " << hi[k] << "]";
        throw std::invalid_argument(msg.str());
      }
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
  for (int j = std::max(0, value_count); j < kSplineFieldCount; ++j) out.value[static_cast<size_t>(j)] = kNaN;
  if (derivatives == SplineDerivatives::kValue) {
    wheel(side).query(x.data(), value_count, out.value.data(), 0, nullptr);
    return;
  }
  // z and the flange clearance are fields 0 and 1: their derivatives come from one query.
  static_assert(kFieldZ == 0 && kFieldFlangeClearance == 1, "the derivative fields lead the list");
  double d[20];
  wheel(side).query(x.data(), value_count, out.value.data(), derivative_fields, d);
  std::copy(d + 1, d + 4, out.z_gradient.begin());
  std::copy(d + 4, d + 10, out.z_hessian.begin());
  if (derivative_fields == 2) {
    std::copy(d + 11, d + 14, out.clearance_gradient.begin());
  } else {
    out.clearance_gradient.fill(kNaN);
  }
}

ContactPoint SplineContactGeometry::contact_point(WheelSide side, const WheelsetPose& pose,
                                                  const SplineEvaluation& e) const {
  const auto& v = e.value;
  ContactPoint p;
  p.side = side;
  p.s = v[kFieldSWheel];
  p.s_rail = v[kFieldSRail];
  p.theta = v[kFieldTheta];
  p.wheel_point = Eigen::Vector3d(pose.x + v[kFieldWheelX], pose.y + v[kFieldWheelY], pose.z + v[kFieldWheelZ]);
  p.distance = pose.z - v[kFieldZ];
  // The rail point lies vertically below the wheel point; its fitted height is that at z_touch.
  p.rail_point = Eigen::Vector3d(p.wheel_point.x(), p.wheel_point.y(), v[kFieldRailZ]);
  p.normal = Eigen::Vector3d(v[kFieldNormalX], v[kFieldNormalY], v[kFieldNormalZ]).normalized();
  p.contact_angle = v[kFieldContactAngle];
  p.rolling_radius = v[kFieldRollingRadius];
  p.wheel_curvature_lateral = v[kFieldWheelCurvatureLateral];
  p.wheel_curvature_rolling = v[kFieldWheelCurvatureRolling];
  p.rail_curvature_lateral = v[kFieldRailCurvatureLateral];
  p.rail_curvature_rolling = v[kFieldRailCurvatureRolling];
  p.distance_curvature = v[kFieldDistanceCurvature];
  p.is_minimum = true;
  return p;
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
  std::vector<double> data;
  for (const TensorSplineSet& set : wheels_) {
    for (const BSplineBasis& b : set.basis().bases()) {
      data.push_back(b.degree());
      data.insert(data.end(), b.breakpoints().begin(), b.breakpoints().end());
    }
    const Eigen::MatrixXd c = set.coefficients();
    for (Eigen::Index j = 0; j < c.cols(); ++j)
      for (Eigen::Index i = 0; i < c.rows(); ++i) data.push_back(c(i, j));
  }
  return sha256_hex(data.data(), data.size() * sizeof(double));  // x86-64 and AArch64: little-endian
}

}  // namespace wrc
