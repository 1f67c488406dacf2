#include "core/model_interface/query_validation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/geometry/wheelset_geometry.hpp"

namespace wrc {
namespace {

[[noreturn]] void reject(const char* field, double value, const char* rule) {
  std::ostringstream msg;
  msg << "contact query: " << field << " = " << value << " " << rule;
  throw std::invalid_argument(msg.str());
}

std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void require_finite(double value, const char* field) {
  if (!std::isfinite(value)) reject(field, value, "must be finite");
}

}  // namespace

void validate_contact_query(const ContactQuery& q) {
  require_finite(q.pose.y, "pose.y [m]");
  require_finite(q.pose.z, "pose.z [m]");
  require_finite(q.pose.roll, "pose.roll [rad]");
  require_finite(q.pose.yaw, "pose.yaw [rad]");
  if (std::fabs(q.pose.yaw) > kMaxValidatedYaw)
    reject("pose.yaw [rad]", q.pose.yaw, "is beyond the validated range +-0.06 rad of the contact geometry");
  require_finite(q.pose.x, "pose.x [m]");
  require_finite(q.y_dot, "y_dot [m/s]");
  require_finite(q.z_dot, "z_dot [m/s]");
  require_finite(q.roll_dot, "roll_dot [rad/s]");
  require_finite(q.yaw_dot, "yaw_dot [rad/s]");
  require_finite(q.spin_rate, "spin_rate [rad/s]");
  if (!(q.speed > 0.0 && q.speed <= kMaxSpeed)) reject("speed [m/s]", q.speed, ("must be in (0, " + text(kMaxSpeed) + "]").c_str());
  if (!(q.normal_load[0] >= 0.0) || !std::isfinite(q.normal_load[0]))
    reject("normal_load[0] (left) [N]", q.normal_load[0], "must be non-negative and finite");
  if (!(q.normal_load[1] >= 0.0) || !std::isfinite(q.normal_load[1]))
    reject("normal_load[1] (right) [N]", q.normal_load[1], "must be non-negative and finite");
  if (!(q.second_normal_load[0] >= 0.0) || !std::isfinite(q.second_normal_load[0]))
    reject("second_normal_load[0] (left) [N]", q.second_normal_load[0], "must be non-negative and finite");
  if (!(q.second_normal_load[1] >= 0.0) || !std::isfinite(q.second_normal_load[1]))
    reject("second_normal_load[1] (right) [N]", q.second_normal_load[1], "must be non-negative and finite");
  if (std::isinf(q.second_tracked_s_wheel[0]))
    reject("second_tracked_s_wheel[0] (left) [m]", q.second_tracked_s_wheel[0], "must be finite or NaN (none)");
  if (std::isinf(q.second_tracked_s_wheel[1]))
    reject("second_tracked_s_wheel[1] (right) [m]", q.second_tracked_s_wheel[1], "must be finite or NaN (none)");
  if (q.formulation != ContactFormulation::kRigid && q.formulation != ContactFormulation::kElastic)
    reject("formulation", static_cast<double>(q.formulation), "is not kRigid or kElastic");
  const ContactMaterial& m = q.material;
  if (!(m.shear_modulus > 0.0 && m.shear_modulus <= kMaxShearModulus))
    reject("material.shear_modulus [Pa]", m.shear_modulus, ("must be in (0, " + text(kMaxShearModulus) + "]").c_str());
  if (!(m.poisson_ratio > kMinPoissonRatio && m.poisson_ratio < kMaxPoissonRatio))
    reject("material.poisson_ratio [-]", m.poisson_ratio,
           ("must be in (" + text(kMinPoissonRatio) + ", " + text(kMaxPoissonRatio) + ")").c_str());
  if (!(m.friction >= 0.0 && m.friction <= kMaxFriction))
    reject("material.friction [-]", m.friction, ("must be in [0, " + text(kMaxFriction) + "]").c_str());
  auto check_grid = [](const char* field, int count) {
    if (count >= kMinFastsimGrid && count <= kMaxFastsimGrid) return;
    reject(field, count, ("must be in " + std::to_string(kMinFastsimGrid) + ".." + std::to_string(kMaxFastsimGrid)).c_str());
  };
  check_grid("fastsim_elements", q.fastsim_elements);
  check_grid("fastsim_strips", q.fastsim_strips);
}

}  // namespace wrc
