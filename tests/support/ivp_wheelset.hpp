// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The "wheelset" problem of the IVP test set (Simeon, Fuehrer, Rentrop 1991; Bari test set for IVP
/// solvers): one wheelset with conical wheels running on two rails of circular cross-section, rigid
/// one-point contact per wheel, written as an index-2 DAE of dimension 17 in the implicit form
/// F(t, y, y') = 0, and its integration with SUNDIALS IDA. It is the validation case of the project's
/// IDA set-up against a published reference solution (docs/ivp-wheelset.md).
///
/// Frame (the test set's, not wrc's track frame of docs/conventions.md): x lateral (towards the
/// "left" wheel, the one at positive x), y vertical and up, z longitudinal (the rolling direction);
/// the frame moves forward with the constant speed V, so x, y, z are displacements from the nominal
/// position of the wheelset centre. theta is the yaw about y, phi the roll about the yawed z axis;
/// body-to-frame rotation R = R_y(theta) R_z(phi). Each wheel's contact point is described by its
/// lateral body coordinate xi (along the axle) and its angle psi on the wheel circumference.
///
/// State order: the test set's, so that y compares component by component with its reference:
/// positions, velocities, spin-rate perturbation, contact parameters (right wheel first), then the
/// two multipliers (normal-contact forces), which the test set scales by 1e-4.

#include <array>
#include <functional>

#include "core/dynamics/run_counters.hpp"

namespace wrc {

/// Number of unknowns of the wheelset DAE.
constexpr int kIvpWheelsetDimension = 17;

/// One value per unknown, in the order of IvpWheelsetComponent.
using IvpWheelsetVector = std::array<double, kIvpWheelsetDimension>;

/// Index of each unknown in IvpWheelsetVector (the test set's order).
enum IvpWheelsetComponent : int {
  kIvpLateral = 0,             ///< x: lateral displacement of the wheelset centre [m]
  kIvpVertical = 1,            ///< y: vertical displacement, up [m]
  kIvpLongitudinal = 2,        ///< z: longitudinal displacement from the frame moving at V [m]
  kIvpYaw = 3,                 ///< theta: yaw angle [rad]
  kIvpRoll = 4,                ///< phi: roll angle [rad]
  kIvpLateralRate = 5,         ///< x' [m/s]
  kIvpVerticalRate = 6,        ///< y' [m/s]
  kIvpLongitudinalRate = 7,    ///< z' [m/s]
  kIvpYawRate = 8,             ///< theta' [rad/s]
  kIvpRollRate = 9,            ///< phi' [rad/s]
  kIvpSpinRate = 10,           ///< beta': spin rate minus the nominal V / r0 [rad/s]
  kIvpRightContactAngle = 11,  ///< psi_R: angle of the right contact point on the circumference [rad]
  kIvpRightContactXi = 12,     ///< xi_R: body lateral coordinate of the right contact point [m] (< 0)
  kIvpLeftContactAngle = 13,   ///< psi_L: angle of the left contact point on the circumference [rad]
  kIvpLeftContactXi = 14,      ///< xi_L: body lateral coordinate of the left contact point [m] (> 0)
  kIvpLeftMultiplier = 15,     ///< lambda_L * 1e-4: left constraint multiplier [1e4 N]
  kIvpRightMultiplier = 16,    ///< lambda_R * 1e-4: right constraint multiplier [1e4 N]
};

/// Scale between a multiplier component of the state and the multiplier in newtons [N per unit].
constexpr double kIvpMultiplierScale = 1e4;

/// Parameters of the problem; the defaults are the test set's (a small-scale wheelset model).
struct IvpWheelsetParameters {
  double mass = 16.08;                   ///< wheelset mass m [kg]
  double gravity = 9.81;                 ///< gravitational acceleration g [m/s^2]
  double speed = 30.0;                   ///< forward speed V [m/s]
  double nominal_radius = 0.1;           ///< nominal rolling radius r0 [m]
  double spin_inertia = 0.0605;          ///< moment of inertia about the axle [kg m^2]
  double yaw_roll_inertia = 0.366;       ///< moment of inertia about the yaw and roll axes [kg m^2]
  double carried_mass = 0.0;             ///< mass resting on the axle (a vertical load m_c g) [kg]
  double friction = 0.12;                ///< friction coefficient mu [-]
  double spring_half_distance = 0.19;    ///< lateral half distance of the longitudinal springs [m]
  double lateral_stiffness = 6400.0;     ///< lateral spring per side (force -2 c_x x) [N/m]
  double longitudinal_stiffness = 6400.0;  ///< longitudinal spring per side (force -2 c_z z) [N/m]
  double hertz_coefficient_e = 1.3537956;  ///< the test set's "E" in the contact-ellipse size [-]
  double hertz_coefficient_g = 0.7115218;  ///< the test set's "GG" in the contact-ellipse size [-]
  double poisson = 0.28;                 ///< Poisson's ratio nu [-]
  double shear_modulus = 7.92e10;        ///< shear modulus G [Pa]
  double kalker_c11 = 4.72772197;        ///< Kalker coefficient C11 [-]
  double kalker_c22 = 4.27526987;        ///< Kalker coefficient C22 [-]
  double kalker_c23 = 1.97203505;        ///< Kalker coefficient C23 [-]
  double cone_angle = 0.0262;            ///< cone angle delta0 of the wheel tread [rad]
  double contact_half_distance = 0.1506; ///< half distance a of the nominal contact points [m]
  double rail_radius = 0.06;             ///< radius of the rail head's circular profile [m]
  double rail_margin = 1e-5;             ///< margin to the edge of the rail circle (derailment) [m]
  double wheel_inner_limit = 0.0;        ///< smallest |xi| on the wheel profile [m]
  double wheel_outer_limit = 4.0;        ///< largest |xi| on the wheel profile [m]
};

/// Time, unknowns and their time derivatives.
struct IvpWheelsetState {
  double t = 0;              ///< time [s]
  IvpWheelsetVector y{};     ///< unknowns (units per IvpWheelsetComponent)
  IvpWheelsetVector yp{};    ///< their time derivatives (units per IvpWheelsetComponent, per second)
};

/// The test set's consistent initial values at t = 0 (for the default parameters): the wheelset
/// at rest in the frame, slightly displaced (x = 1.4941 mm), with the accelerations that balance it.
IvpWheelsetState ivp_wheelset_initial_state();

/// Time of the published reference solution [s].
constexpr double kIvpWheelsetReferenceTime = 10.0;

/// The test set's reference solution at t = 10 s (DASSL, rtol = atol = 1e-9 on positions,
/// velocities and contact parameters, multipliers excluded from the error test).
IvpWheelsetVector ivp_wheelset_reference_solution();

/// Outcome of one residual evaluation.
enum class IvpWheelsetResidualStatus {
  kOk,                       ///< F evaluated
  kOffWheelProfile,          ///< a contact point left the wheel profile's range (derailment)
  kOffRailProfile,           ///< a contact point left the rail circle's range (derailment)
  kSingularContactAngles,    ///< the two contact normals are (almost) parallel: no normal forces
};

/// Short English name of a status, for messages.
const char* to_string(IvpWheelsetResidualStatus status);

/// The residual F(t, y, y') of the index-2 DAE:
/// rows 0-4 kinematics p' - v [m/s, rad/s]; rows 5-7 Newton's law m v' - f [N]; rows 8-10 Euler's
/// equations about the body's vertical, roll and spin axes [N m]; rows 11-14 the contact conditions
/// (wheel normal perpendicular to the rail tangent and to the rolling direction) [-]; rows 15-16 the
/// velocity form of the contact constraints G(p, q) v [m/s]. Straight track without cant.
/// @param y unknowns, @param yp their derivatives (units per IvpWheelsetComponent).
/// @param residual output, 17 values (units above); left unchanged unless the status is kOk.
IvpWheelsetResidualStatus ivp_wheelset_residual(const IvpWheelsetParameters& parameters,
                                                const IvpWheelsetVector& y,
                                                const IvpWheelsetVector& yp,
                                                IvpWheelsetVector& residual);

/// What the constraints and the contact give at one state (index 0 = left wheel, 1 = right).
struct IvpWheelsetContactState {
  std::array<double, 2> gap{};           ///< position constraint: rail height minus wheel-point height [m]
  std::array<double, 2> gap_rate{};      ///< velocity constraint G(p, q) v [m/s]
  std::array<double, 2> normal_rail_tangent{};  ///< wheel normal . rail tangent (contact condition) [-]
  std::array<double, 2> normal_rolling{};       ///< wheel normal . rolling direction (contact condition) [-]
  std::array<double, 2> contact_angle{};  ///< angle of the contact plane, > 0 towards the track centre [rad]
  std::array<double, 2> normal_force{};   ///< normal force on the wheel [N]
};

/// The constraint residuals, contact angles and normal forces at a state.
/// @throws std::runtime_error naming the status when the contact cannot be evaluated (derailment).
IvpWheelsetContactState ivp_wheelset_contact_state(const IvpWheelsetParameters& parameters,
                                                   const IvpWheelsetVector& y);

/// Settings of the IDA integration.
struct IvpWheelsetIntegratorOptions {
  double relative_tolerance = 1e-9;   ///< IDA rtol [-]
  double absolute_tolerance = 1e-9;   ///< IDA atol for every component in the error test [component units]
  /// true: positions and velocities are error-tested, the 6 algebraic unknowns (contact parameters
  /// and multipliers) are not (IDASetSuppressAlg). false: as the test set did with DASSL, only the
  /// multipliers are left out (absolute tolerance 1e10 on them).
  bool suppress_algebraic_error_test = true;
  long max_steps = 2'000'000;         ///< bound on the internal steps to t_end [-]
};

/// The end of a run.
struct IvpWheelsetRun {
  IvpWheelsetState final_state;   ///< state at t_end (units per IvpWheelsetComponent)
  RunCounters counters;           ///< IDA statistics (one run, no restarts: the event fields stay 0)
};

/// Called after every internal step with the state there (for monitoring, e.g. constraint drift).
using IvpWheelsetStepObserver = std::function<void(const IvpWheelsetState&)>;

/// Integrates the DAE with IDA (BDF, dense direct linear solver with a difference-quotient
/// Jacobian, algebraic unknowns marked by IDASetId) from `initial` to `t_end`, stepping with a stop
/// time so that the last state is at t_end exactly. `initial` must be consistent (as
/// ivp_wheelset_initial_state() is): IDACalcIC is not used, because with the wheelset at rest the
/// index-2 constraint G v does not depend on the algebraic unknowns, so the system IDACalcIC would
/// solve is singular (tried: on perturbed values it reports success and leaves |F| ~ 0.08 N); the
/// consistency is checked instead (max |F| <= 1e-6 in the units of F).
/// @param t_end end time [s], > initial.t.
/// @throws std::invalid_argument for bad tolerances, t_end or an inconsistent initial state;
/// std::runtime_error naming the SUNDIALS function and its flag when a call fails.
IvpWheelsetRun integrate_ivp_wheelset(const IvpWheelsetParameters& parameters,
                                      const IvpWheelsetState& initial, double t_end,
                                      const IvpWheelsetIntegratorOptions& options,
                                      const IvpWheelsetStepObserver& observer = {});

}  // namespace wrc
