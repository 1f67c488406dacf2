// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle/bogie_steady_curving.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

[[noreturn]] void refuse(const char* field, const char* unit, double value, const char* rule) {
  throw std::invalid_argument(std::string("BogieCurvingParameters: ") + field + " = " + shortest_number_text(value) +
                              " " + unit + " must be " + rule);
}

void finite(const char* field, const char* unit, double value) {
  if (!std::isfinite(value)) refuse(field, unit, value, "finite");
}

void positive(const char* field, const char* unit, double value) {
  if (!(std::isfinite(value) && value > 0.0)) refuse(field, unit, value, "finite and > 0");
}

void not_negative(const char* field, const char* unit, double value) {
  if (!(std::isfinite(value) && value >= 0.0)) refuse(field, unit, value, "finite and >= 0");
}

using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

// x of wheelset i [m]: +a leading, -a trailing.
double wheelset_x(const BogieCurvingParameters& p, int i) { return i == 0 ? p.semi_wheelbase : -p.semi_wheelbase; }

// The forces of docs/bogie-curving.md ("Forces") from the displacements, and each body's balance:
// balance[k] = sum of the forces (moments) on body k, rows as in q; largest[k] = its largest term.
struct Forces {
  BogieCurvingResult result;
  Vector6 balance = Vector6::Zero();
  Vector6 largest = Vector6::Zero();
};

Forces forces_at(const BogieCurvingParameters& p, const Vector6& q) {
  const double kappa = p.curvature;
  const double a = p.semi_wheelbase;
  const double b0 = p.contact_half_distance;
  const double r0 = p.rolling_radius;
  const double yaw_stiffness = 2.0 * p.primary_longitudinal_stiffness * p.primary_semi_spacing * p.primary_semi_spacing;
  Forces f;
  BogieCurvingResult& r = f.result;
  r.frame_lateral = q[0];
  r.frame_yaw = q[1];
  const auto add = [&f](int row, std::initializer_list<double> terms) {
    for (double t : terms) {
      f.balance[row] += t;
      f.largest[row] = std::max(f.largest[row], std::abs(t));
    }
  };
  for (int i = 0; i < 2; ++i) {
    WheelsetCurvingState& w = r.wheelsets[i];
    const double x = wheelset_x(p, i);
    w.lateral = q[2 + 2 * i];
    w.yaw = q[3 + 2 * i];
    // Creepages (wheel material's velocity at the contact over V; docs/bogie-curving.md).
    w.longitudinal_creepage_left = -(b0 * kappa + p.conicity * w.lateral / r0);
    w.lateral_creepage = -w.yaw;
    w.spin_creepage_left = kappa - p.contact_angle_slope * w.lateral / r0;
    w.spin_creepage_right = w.spin_creepage_left;
    // Linear creep (core/contact/linear_creep.hpp): Fx = -f11 xi_x, Fy = -f22 xi_y - f23 phi,
    // Mz = f23 xi_y - f33 phi; the right wheel's xi_x is the left one's negative.
    w.longitudinal_creep_force_left = -p.f11 * w.longitudinal_creepage_left;
    const double lateral_left = -p.f22 * w.lateral_creepage - p.f23 * w.spin_creepage_left;
    const double lateral_right = -p.f22 * w.lateral_creepage - p.f23 * w.spin_creepage_right;
    const double spin_moment_left = p.f23 * w.lateral_creepage - p.f33 * w.spin_creepage_left;
    const double spin_moment_right = p.f23 * w.lateral_creepage - p.f33 * w.spin_creepage_right;
    w.lateral_creep_force = lateral_left + lateral_right;
    // x F_y - y F_x with the left contact at y = +b0, the right one at -b0 (F_x right = -F_x left).
    const double longitudinal_moment = -2.0 * b0 * w.longitudinal_creep_force_left;
    w.creep_yaw_moment = longitudinal_moment + spin_moment_left + spin_moment_right;
    w.gravitational_force = -p.gravitational_lateral_stiffness * w.lateral;
    // Primary deflections: the track centre line at x lies a^2 kappa / 2 off the frame centre's
    // tangent, and its tangent is turned by x kappa.
    w.primary_lateral_deflection = w.lateral + 0.5 * a * a * kappa - r.frame_lateral - x * r.frame_yaw;
    w.primary_yaw_deflection = w.yaw + x * kappa - r.frame_yaw;
    w.primary_lateral_force = -2.0 * p.primary_lateral_stiffness * w.primary_lateral_deflection;
    w.primary_yaw_moment = -yaw_stiffness * w.primary_yaw_deflection;
    const double load = p.wheelset_mass * p.lateral_acceleration + p.wheelset_lateral_force;
    add(2 + 2 * i, {lateral_left, lateral_right, w.gravitational_force, w.primary_lateral_force, load});
    add(3 + 2 * i, {longitudinal_moment, spin_moment_left, spin_moment_right, w.primary_yaw_moment});
    // The same springs on the frame, reversed, the lateral one acting at x.
    add(0, {-w.primary_lateral_force});
    add(1, {-w.primary_yaw_moment, -x * w.primary_lateral_force});
  }
  r.secondary_lateral_force = -p.secondary_lateral_stiffness * (r.frame_lateral - p.body_lateral_offset);
  r.secondary_yaw_moment = -p.secondary_yaw_stiffness * (r.frame_yaw - p.body_yaw);
  add(0, {r.secondary_lateral_force, p.frame_mass * p.lateral_acceleration + p.frame_lateral_force});
  add(1, {r.secondary_yaw_moment});
  r.pure_rolling_lateral = -r0 * b0 * kappa / p.conicity;
  return f;
}

// K q = F of docs/bogie-curving.md ("The linear system"), every row minus a body's balance.
void assemble(const BogieCurvingParameters& p, Matrix6& k, Vector6& rhs) {
  const double kappa = p.curvature;
  const double a = p.semi_wheelbase;
  const double b0 = p.contact_half_distance;
  const double r0 = p.rolling_radius;
  const double ky2 = 2.0 * p.primary_lateral_stiffness;  // per wheelset
  const double kpsi = 2.0 * p.primary_longitudinal_stiffness * p.primary_semi_spacing * p.primary_semi_spacing;
  const double creep_lateral = 2.0 * p.f22;                        // 2 f22 [N]
  const double creep_yaw = 2.0 * p.f11 * b0 * p.conicity / r0;     // 2 f11 b0 lambda / r0 [N]
  const double spin_lateral = 2.0 * p.f23 * p.contact_angle_slope / r0;  // [N/m]
  const double spin_yaw = 2.0 * p.f33 * p.contact_angle_slope / r0;      // [N]
  k.setZero();
  rhs.setZero();
  // Frame, lateral and yaw.
  k(0, 0) = p.secondary_lateral_stiffness;
  k(1, 1) = p.secondary_yaw_stiffness;
  rhs[0] = p.frame_mass * p.lateral_acceleration + p.frame_lateral_force + p.secondary_lateral_stiffness * p.body_lateral_offset;
  rhs[1] = p.secondary_yaw_stiffness * p.body_yaw;
  for (int i = 0; i < 2; ++i) {
    const double x = wheelset_x(p, i);
    const int y = 2 + 2 * i;
    const int psi = 3 + 2 * i;
    // Frame lateral: sum 2 k_y (y_f + x psi_f - y_i) + k_sy y_f = ... + 2 k_y a^2 kappa / 2.
    k(0, 0) += ky2;
    k(0, 1) += ky2 * x;
    k(0, y) -= ky2;
    rhs[0] += ky2 * 0.5 * a * a * kappa;
    // Frame yaw: sum [2 k_y x (y_f + x psi_f - y_i) + k_psi (psi_f - psi_i)] + k_spsi psi_f = ...
    k(1, 0) += ky2 * x;
    k(1, 1) += ky2 * x * x + kpsi;
    k(1, y) -= ky2 * x;
    k(1, psi) -= kpsi;
    rhs[1] += ky2 * x * 0.5 * a * a * kappa + kpsi * x * kappa;
    // Wheelset lateral: 2 k_y (y_i - y_f - x psi_f) + (k_g - 2 f23 eps / r0) y_i - 2 f22 psi_i = ...
    k(y, 0) = -ky2;
    k(y, 1) = -ky2 * x;
    k(y, y) = ky2 + p.gravitational_lateral_stiffness - spin_lateral;
    k(y, psi) = -creep_lateral;
    rhs[y] = -ky2 * 0.5 * a * a * kappa - 2.0 * p.f23 * kappa + p.wheelset_mass * p.lateral_acceleration +
             p.wheelset_lateral_force;
    // Wheelset yaw: (2 f11 b0 lambda / r0 - 2 f33 eps / r0) y_i + (k_psi + 2 f23) psi_i - k_psi psi_f = ...
    k(psi, 1) = -kpsi;
    k(psi, y) = creep_yaw - spin_yaw;
    k(psi, psi) = kpsi + 2.0 * p.f23;
    rhs[psi] = -2.0 * p.f11 * b0 * b0 * kappa - 2.0 * p.f33 * kappa - kpsi * x * kappa;
  }
}

}  // namespace

void BogieCurvingParameters::validate() const {
  finite("curvature", "[1/m]", curvature);
  finite("lateral_acceleration", "[m/s^2]", lateral_acceleration);
  finite("frame_lateral_force", "[N]", frame_lateral_force);
  finite("wheelset_lateral_force", "[N]", wheelset_lateral_force);
  positive("frame_mass", "[kg]", frame_mass);
  positive("wheelset_mass", "[kg]", wheelset_mass);
  positive("semi_wheelbase", "[m]", semi_wheelbase);
  positive("conicity", "[-]", conicity);
  positive("rolling_radius", "[m]", rolling_radius);
  positive("contact_half_distance", "[m]", contact_half_distance);
  positive("f11", "[N]", f11);
  positive("f22", "[N]", f22);
  not_negative("gravitational_lateral_stiffness", "[N/m]", gravitational_lateral_stiffness);
  not_negative("f23", "[N m]", f23);
  not_negative("f33", "[N m^2]", f33);
  finite("contact_angle_slope", "[rad/m]", contact_angle_slope);
  not_negative("primary_longitudinal_stiffness", "[N/m]", primary_longitudinal_stiffness);
  not_negative("primary_lateral_stiffness", "[N/m]", primary_lateral_stiffness);
  positive("primary_semi_spacing", "[m]", primary_semi_spacing);
  not_negative("secondary_lateral_stiffness", "[N/m]", secondary_lateral_stiffness);
  not_negative("secondary_yaw_stiffness", "[N m/rad]", secondary_yaw_stiffness);
  finite("body_lateral_offset", "[m]", body_lateral_offset);
  finite("body_yaw", "[rad]", body_yaw);
  // docs/bogie-curving.md, "Existence": det K > 0 unless the frame is free.
  if (primary_lateral_stiffness == 0.0) {
    if (secondary_lateral_stiffness == 0.0)
      throw std::invalid_argument(
          "BogieCurvingParameters: primary_lateral_stiffness = 0 [N/m] and secondary_lateral_stiffness = 0 [N/m]: "
          "nothing holds the frame laterally");
    if (primary_longitudinal_stiffness == 0.0 && secondary_yaw_stiffness == 0.0)
      throw std::invalid_argument(
          "BogieCurvingParameters: primary_lateral_stiffness, primary_longitudinal_stiffness and "
          "secondary_yaw_stiffness = 0: nothing holds the frame in yaw");
  }
}

double lateral_acceleration_of_cant_deficiency(double cant_deficiency, double curvature, double gravity) {
  if (curvature == 0.0) return 0.0;
  return (curvature > 0.0 ? -1.0 : 1.0) * gravity * cant_deficiency;
}

BogieCurvingResult bogie_steady_curving(const BogieCurvingParameters& parameters) {
  parameters.validate();
  Matrix6 k;
  Vector6 rhs;
  assemble(parameters, k, rhs);
  const Eigen::FullPivLU<Matrix6> lu(k);
  // Only the optional spin terms can make K singular once validate() has passed (a negative net
  // lateral stiffness k_g - 2 f23 eps / r0 large enough).
  if (!lu.isInvertible())
    throw std::invalid_argument("bogie_steady_curving: K is singular (the spin terms f23 = " +
                                shortest_number_text(parameters.f23) + " [N m], contact_angle_slope = " +
                                shortest_number_text(parameters.contact_angle_slope) +
                                " [rad/m] cancel the lateral stiffness)");
  const Vector6 q = lu.solve(rhs);
  Forces f = forces_at(parameters, q);
  double residual = 0.0;
  for (int row = 0; row < 6; ++row)
    if (f.largest[row] > 0.0) residual = std::max(residual, std::abs(f.balance[row]) / f.largest[row]);
  f.result.relative_residual = residual;
  return f.result;
}

}  // namespace wrc
