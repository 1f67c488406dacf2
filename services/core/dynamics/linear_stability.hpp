// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Linear stability of the wheelset on straight track (docs/stability.md): the equations of
/// wheelset_equations.hpp linearised about the centred steady state at speed V, numerically from
/// their residual with the run's own contact model, reduced to the state-space matrix of the
/// differential states, and its eigenvalues; the linear critical speed where the largest real part
/// crosses 0.
///
/// The steady state: y = yaw = 0 exactly, all rates 0, z and roll from the contact (rigid: both
/// gaps 0; elastic: the static Hertz approach), the normal forces carrying the load, and the spin
/// rate at which the axle moment vanishes. It needs lateral_force = 0 (with a lateral load the
/// wheelset is not centred).
///
/// The reduction. Rigid contact (13 unknowns, index 2): the linearised constraints G dq = 0 and
/// G dv = 0 give dmu = 0 and leave 2 of the 4 coordinates free; with q = T p, p = (y, yaw), and the
/// normal forces eliminated through the acceleration-level constraint, the state is
/// (y, yaw, y', yaw', Omega): 5 eigenvalues, none of them from z and roll. Elastic contact (9
/// unknowns, an ODE): A = -(dF/dy')^-1 dF/dy over (q, v, Omega), 9 eigenvalues, the vertical and
/// roll ones physical (the wheelset on its Hertz springs).

#include <complex>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/wheelset_equations.hpp"
#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// What a mode moves most, by its share of kinetic energy.
enum class ModeKind {
  kLateralYaw,    ///< y and yaw (hunting, the kinematic mode, the creep-damped lateral mode)
  kVerticalRoll,  ///< z and roll (elastic contact only: the wheelset on its Hertz springs)
  kSpin,          ///< the spin perturbation Omega - V / r0 (a real, creep-damped mode)
  kVerticalPitch, ///< z and pitch of a vehicle's car body or frame (bounce and pitch on its springs)
};

/// "lateral-yaw", "vertical-roll", "spin", "vertical-pitch".
const char* mode_kind_name(ModeKind kind);

/// One eigenvalue of the linearised wheelset.
struct StabilityMode {
  std::complex<double> eigenvalue;  ///< lambda [1/s]: real part the growth rate, imaginary part [rad/s]
  ModeKind kind = ModeKind::kLateralYaw;
  double frequency() const;      ///< |Im lambda| / (2 pi) [Hz]
  double damping_ratio() const;  ///< -Re lambda / |lambda| [-] (< 0: unstable)
};

/// The centred steady state at one speed.
struct CentredSteadyState {
  double speed = 0;             ///< V [m/s]
  std::vector<double> state;    ///< the unknowns of wheelset_equations.hpp (13 rigid, 9 elastic)
  ContactResult contact;        ///< the contact there (patches with their a, b, normal forces)
  double z_reference = 0;       ///< height where the vertical suspension is relaxed [m]
  /// Largest |F(y, 0)| of the rows of motion, each scaled by its typical size (force_scale for
  /// forces, force_scale x 1 m for moments) [-]: how far from steady the state is.
  double residual = 0;
};

/// The linearised wheelset at one speed.
struct LinearisedWheelset {
  double speed = 0;                      ///< V [m/s]
  Eigen::MatrixXd state_matrix;          ///< A of x' = A x [SI]
  std::vector<std::string> state_names;  ///< the states x, with units
  std::vector<StabilityMode> modes;      ///< every eigenvalue, largest real part first
  CentredSteadyState steady;
  /// The mode with the largest real part (of a complex pair, the one with Im >= 0).
  const StabilityMode& least_damped() const;
};

/// The linear critical speed: where the largest real part of the eigenvalues crosses 0 from below.
struct CriticalSpeed {
  bool found = false;      ///< false: no crossing in the scanned range
  double speed = 0;        ///< V_c [m/s]
  double frequency = 0;    ///< of the mode crossing there [Hz] (0: a real eigenvalue, divergence)
  ModeKind kind = ModeKind::kLateralYaw;
  int linearisations = 0;  ///< linearisations of the refinement [-]
};

/// Validated speeds from `from` to `to` (inclusive within rounding) every `step` [m/s].
/// @throws std::invalid_argument naming the bad value: any of them not finite, from <= 0, to < from,
///         step <= 0, or more than kMaxStabilitySpeeds speeds.
std::vector<double> stability_speeds(double from, double to, double step);
inline constexpr long kMaxStabilitySpeeds = 10000;

class LinearStability {
 public:
  /// @param parameters the wheelset (its speed is replaced by each analysis speed);
  ///        lateral_force must be 0.
  /// @param contact the contact model (in-process or any other evaluator).
  /// @param nominal_radius r0 of the wheel profile [m], > 0.
  /// @throws std::invalid_argument naming the value for lateral_force != 0, invalid parameters,
  ///         a null contact or a bad radius.
  LinearStability(WheelsetParameters parameters, std::shared_ptr<ContactEvaluator> contact, double nominal_radius);

  ContactFormulation formulation() const { return formulation_; }
  const WheelsetParameters& parameters() const { return parameters_; }

  /// The centred steady state at speed [m/s].
  /// @throws std::invalid_argument naming a speed that is not finite and > 0; std::runtime_error
  ///         when the contact finds no steady state.
  CentredSteadyState steady_state(double speed);

  /// The state-space matrix and eigenvalues at speed [m/s] (central differences of the residual
  /// about steady_state(speed)). Same exceptions as steady_state().
  LinearisedWheelset linearise(double speed);

  /// The critical speed within the scan (linearisations at increasing speeds): the first pair of
  /// neighbours whose largest real parts go from < 0 to >= 0, refined by the Illinois variant of
  /// regula falsi to relative_tolerance of the speed.
  CriticalSpeed critical_speed(const std::vector<LinearisedWheelset>& scan, double relative_tolerance = 1e-6);

 private:
  WheelsetParameters parameters_;
  std::shared_ptr<ContactEvaluator> contact_;
  double nominal_radius_;
  ContactFormulation formulation_;
};

}  // namespace wrc
