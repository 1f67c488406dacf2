// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wickens_wheelset.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace wrc {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  if (ok) return;
  std::ostringstream msg;
  msg << "WickensWheelset: " << name << " = " << value << " must be " << rule;
  throw std::invalid_argument(msg.str());
}

}  // namespace

double WickensCriticalPoint::frequency() const { return angular_frequency / (2.0 * M_PI); }

void WickensWheelset::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  require(positive(mass), "mass [kg]", mass, "finite and > 0");
  require(positive(yaw_inertia), "yaw_inertia [kg m^2]", yaw_inertia, "finite and > 0");
  require(positive(conicity), "conicity [-]", conicity, "finite and > 0");
  require(positive(rolling_radius), "rolling_radius [m]", rolling_radius, "finite and > 0");
  require(positive(contact_half_distance), "contact_half_distance [m]", contact_half_distance, "finite and > 0");
  require(positive(f11), "f11 [N]", f11, "finite and > 0");
  require(positive(f22), "f22 [N]", f22, "finite and > 0");
  require(std::isfinite(lateral_stiffness), "lateral_stiffness [N/m]", lateral_stiffness, "finite");
  require(std::isfinite(yaw_stiffness), "yaw_stiffness [N m/rad]", yaw_stiffness, "finite");
  require(non_negative(lateral_damping), "lateral_damping [N s/m]", lateral_damping, "finite and >= 0");
  require(non_negative(yaw_damping), "yaw_damping [N m s/rad]", yaw_damping, "finite and >= 0");
}

Eigen::Matrix4d WickensWheelset::state_matrix(double speed) const {
  validate();
  require(std::isfinite(speed) && speed > 0.0, "speed [m/s]", speed, "finite and > 0");
  const double b0 = contact_half_distance;
  const double lateral_creep = 2.0 * f22;                 // [N]
  const double longitudinal_creep = 2.0 * f11 * b0 * b0;  // [N m^2]
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a(0, 2) = 1.0;
  a(1, 3) = 1.0;
  // m y'' = -(2 f22 / V + c_y) y' + 2 f22 psi - k_y y
  a(2, 0) = -lateral_stiffness / mass;
  a(2, 1) = lateral_creep / mass;
  a(2, 2) = -(lateral_creep / speed + lateral_damping) / mass;
  // I psi'' = -(2 f11 b0^2 / V + c_psi) psi' - 2 f11 b0 lambda / r0 y - k_psi psi
  a(3, 0) = -2.0 * f11 * b0 * conicity / rolling_radius / yaw_inertia;
  a(3, 1) = -yaw_stiffness / yaw_inertia;
  a(3, 3) = -(longitudinal_creep / speed + yaw_damping) / yaw_inertia;
  return a;
}

Eigen::Vector4cd WickensWheelset::eigenvalues(double speed) const {
  return Eigen::EigenSolver<Eigen::Matrix4d>(state_matrix(speed), false).eigenvalues();
}

double WickensWheelset::kinematic_angular_frequency(double speed) const {
  return speed * std::sqrt(conicity / (rolling_radius * contact_half_distance));
}

std::optional<WickensCriticalPoint> WickensWheelset::critical_point() const {
  validate();
  // s = i omega in the characteristic polynomial
  //   (m s^2 + F s / V + k_y)(I s^2 + C b0^2 s / V + k_psi) + F C b0 lambda / r0 = 0,
  // F = 2 f22, C = 2 f11: the imaginary part gives omega_c (independent of V), the real part V_c.
  const double b0 = contact_half_distance;
  const double f = 2.0 * f22;
  const double c = 2.0 * f11 * b0 * b0;
  const double omega2 = (f * yaw_stiffness + c * lateral_stiffness) / (f * yaw_inertia + c * mass);
  if (!(omega2 >= 0.0)) return std::nullopt;
  const double detuning = (lateral_stiffness - mass * omega2) / f;
  const double denominator = conicity / (rolling_radius * b0) - detuning * detuning;
  if (!(denominator > 0.0)) return std::nullopt;
  return WickensCriticalPoint{std::sqrt(omega2 / denominator), std::sqrt(omega2)};
}

}  // namespace wrc
