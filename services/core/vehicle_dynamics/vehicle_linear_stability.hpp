// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Linear stability of a vehicle on straight, level track (docs/vehicle.md, "Linear stability"):
/// its equations (vehicle_equations.hpp) linearised about its rest state at speed V
/// (vehicle_equilibrium.hpp), E dx' + J dx = 0 with J = dF/dy and E = dF/dy', and the eigenvalues
/// of that pencil. Elastic contact: every unknown is differential and E invertible, the
/// eigenvalues those of -E^-1 J. Rigid contact (index 2): the generalised eigenvalues of (-J, E)
/// by QZ; the constraints make 8 of each wheelset's 13 infinite (z, roll, their rates, the normal
/// forces and multipliers), which are left out, so a wheelset keeps y, yaw, their rates and its
/// spin, as the lone wheelset's reduced model does (core/dynamics/linear_stability.hpp).

#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/linear_stability.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"

namespace wrc {

/// One eigenvalue of the linearised vehicle.
struct VehicleMode {
  std::complex<double> eigenvalue;  ///< lambda [1/s]: real part the growth rate, imaginary part [rad/s]
  /// What it moves most by kinetic energy: lateral-yaw (y and yaw of any body), vertical-roll (a
  /// car body's or frame's roll; a wheelset's z and roll, on its Hertz springs), vertical-pitch (a
  /// car body's or frame's z and pitch), spin (a car body's sway, lateral and roll together, is
  /// the kind with the larger share)
  ModeKind kind = ModeKind::kLateralYaw;
  size_t body = 0;       ///< the body with the largest share of its kinetic energy [-]
  double body_share = 0; ///< that share [-]
  double frequency() const;      ///< |Im lambda| / (2 pi) [Hz]
  double damping_ratio() const;  ///< -Re lambda / |lambda| [-] (< 0: unstable)
};

/// The linearised vehicle at one speed.
struct LinearisedVehicle {
  double speed = 0;                ///< V [m/s]
  std::vector<VehicleMode> modes;  ///< every finite eigenvalue, largest real part first
  std::vector<double> rest_state;  ///< the state linearised about (vehicle_equations.hpp's layout)
  /// The mode with the largest real part (of a complex pair, the one with Im >= 0).
  const VehicleMode& least_damped() const;
};

/// The linear critical speed of a vehicle.
struct VehicleCriticalSpeed {
  bool found = false;      ///< false: no crossing in the scanned range
  double speed = 0;        ///< V_c [m/s]
  VehicleMode mode;        ///< the mode crossing there (frequency 0: a real eigenvalue, divergence)
  int linearisations = 0;  ///< linearisations of the refinement [-]
};

class VehicleLinearStability {
 public:
  /// @param spec the vehicle and the run's common values (material, FASTSIM grid, gravity; its
  ///        speed is replaced by each analysis speed, its tolerances weigh the rest state's Newton
  ///        test); the track must be straight and level without irregularities, the initial state
  ///        at rest, every wheelset without a lateral external force (the rest state is centred).
  /// @param nominal_radius r0 of the wheel profile [m]
  /// @throws std::invalid_argument naming what the analysis cannot take.
  VehicleLinearStability(VehicleRunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius);

  /// The rest state and the eigenvalues at speed [m/s].
  /// @throws std::invalid_argument for a speed that is not finite and > 0; std::runtime_error when
  ///         there is no rest state or the rigid pencil does not split into the expected finite and
  ///         infinite eigenvalues.
  LinearisedVehicle linearise(double speed);

  /// The first crossing of the largest real part through 0 within the scan (linearisations at
  /// increasing speeds), refined to relative_tolerance of the speed.
  VehicleCriticalSpeed critical_speed(const std::vector<LinearisedVehicle>& scan, double relative_tolerance = 1e-6);

 private:
  VehicleRunSpec spec_;
  std::shared_ptr<ContactEvaluator> contact_;
  double nominal_radius_;
};

}  // namespace wrc
