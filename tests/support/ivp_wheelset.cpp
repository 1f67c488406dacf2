// SPDX-License-Identifier: Apache-2.0
#include "support/ivp_wheelset.hpp"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_types.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/dynamics/sundials_support.hpp"

namespace wrc {
namespace {

// The test set's value of pi in the contact-ellipse size (kept to reproduce its reference).
constexpr double kTestSetPi = 3.1415926;
// Smallest |sin(delta_L + delta_R)| for which the two normal forces are resolved.
constexpr double kMinNormalDeterminant = 1e-8;
// Largest max |F| accepted as a consistent initial state (units of the residual rows).
constexpr double kMaxInitialResidual = 1e-6;

// ---------------------------------------------------------------------------------------------
// Small 3-vector algebra in the test set's frame (x lateral, y up, z longitudinal).

struct Vec3 {
  double x = 0;
  double y = 0;
  double z = 0;
};

Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

constexpr Vec3 kVertical{0.0, 1.0, 0.0};

// The rotation R = R_y(yaw) R_z(roll) from body to frame coordinates, with the body axes it maps.
struct Attitude {
  double sin_yaw = 0;
  double cos_yaw = 1;
  double sin_roll = 0;
  double cos_roll = 1;

  Attitude(double yaw, double roll)
      : sin_yaw(std::sin(yaw)), cos_yaw(std::cos(yaw)), sin_roll(std::sin(roll)), cos_roll(std::cos(roll)) {}

  Vec3 to_frame(const Vec3& b) const {
    const double rolled_x = b.x * cos_roll - b.y * sin_roll;
    const double rolled_y = b.x * sin_roll + b.y * cos_roll;
    return {rolled_x * cos_yaw + b.z * sin_yaw, rolled_y, -rolled_x * sin_yaw + b.z * cos_yaw};
  }
  Vec3 axle() const { return to_frame({1.0, 0.0, 0.0}); }           // spin axis
  Vec3 body_vertical() const { return to_frame({0.0, 1.0, 0.0}); }  // yaw equation's axis
  Vec3 roll_axis() const { return {sin_yaw, 0.0, cos_yaw}; }         // the yawed z axis
};

// ---------------------------------------------------------------------------------------------
// Profiles. Both are even in the lateral coordinate, so one function serves both sides.

struct ProfileValue {
  double value = 0;
  double slope = 0;
  double second_derivative = 0;
};

// Conical wheel: radius r(xi) = r0 + tan(delta0) (a - |xi|) [m] at body lateral coordinate xi [m].
bool wheel_profile(const IvpWheelsetParameters& p, double xi, ProfileValue& out) {
  const double abs_xi = std::abs(xi);
  if (abs_xi <= p.wheel_inner_limit || abs_xi >= p.wheel_outer_limit) return false;
  const double taper = std::tan(p.cone_angle);
  out.value = p.nominal_radius + taper * (p.contact_half_distance - abs_xi);
  out.slope = (xi >= 0.0 ? -1.0 : 1.0) * taper;
  out.second_derivative = 0.0;
  return true;
}

// Rail head: a circle of radius R_s centred at |x| = a + R_s sin(delta0), placed so that its point
// of slope tan(delta0) touches the nominal cone; height g(x) [m] in the frame, y up.
bool rail_profile(const IvpWheelsetParameters& p, double x, ProfileValue& out) {
  const double radius = p.rail_radius;
  const double centre = p.contact_half_distance + radius * std::sin(p.cone_angle);
  const double abs_x = std::abs(x);
  if (abs_x >= centre + radius - p.rail_margin || abs_x <= centre - radius + p.rail_margin) return false;
  const double offset = abs_x - centre;
  const double root = std::sqrt(radius * radius - offset * offset);
  out.value = root - p.nominal_radius - std::cos(p.cone_angle) * radius;
  out.slope = (x >= 0.0 ? 1.0 : -1.0) * (-offset) / root;
  out.second_derivative = -radius * radius / (root * root * root);
  return true;
}

// ---------------------------------------------------------------------------------------------
// One wheel's contact: geometry, constraint row, contact conditions and angle.

struct WheelContact {
  double side = 1;          // +1 left (xi > 0), -1 right
  double xi = 0;            // body lateral coordinate of the contact point [m]
  double psi = 0;           // angle on the circumference [rad]
  ProfileValue wheel;       // r, r', r''
  ProfileValue rail;        // g, g', g'' at the contact point's lateral position
  Vec3 body_point;          // contact point in body coordinates [m]
  Vec3 offset;              // contact point minus wheelset centre, frame coordinates [m]
  Vec3 normal;              // wheel surface normal (not normalised) in the frame [-]
  double gap = 0;           // rail height minus wheel point height [m]
  double constraint_row[5] = {0, 0, 0, 0, 0};  // d gap / d (x, y, z, yaw, roll)
  double contact_angle = 0; // > 0 towards the track centre [rad]
  double normal_rail_tangent = 0;  // contact condition 1 [-]
  double normal_rolling = 0;       // contact condition 2 [-]
};

IvpWheelsetResidualStatus evaluate_wheel(const IvpWheelsetParameters& p, const double* y, double side,
                                         double xi, double psi, const Attitude& attitude, WheelContact& c) {
  c.side = side;
  c.xi = xi;
  c.psi = psi;
  if (!wheel_profile(p, xi, c.wheel)) return IvpWheelsetResidualStatus::kOffWheelProfile;
  const double r = c.wheel.value;
  c.body_point = {xi, -r * std::cos(psi), -r * std::sin(psi)};
  c.offset = attitude.to_frame(c.body_point);
  if (!rail_profile(p, y[kIvpLateral] + c.offset.x, c.rail)) return IvpWheelsetResidualStatus::kOffRailProfile;
  c.gap = c.rail.value - (y[kIvpVertical] + c.offset.y);

  // Normal of the surface of revolution (xi, -r cos psi, -r sin psi): proportional to (r', cos psi, sin psi).
  c.normal = attitude.to_frame({c.wheel.slope, std::cos(psi), std::sin(psi)});
  // Common normal: the wheel normal is perpendicular to the rail tangent (1, g', 0) and to the
  // rolling direction (the rails are prismatic along z).
  c.normal_rail_tangent = c.normal.x + c.rail.slope * c.normal.y;
  c.normal_rolling = c.normal.z;
  c.contact_angle = -side * std::atan(c.normal.x / c.normal.y);

  // Gradient of the gap in the positions at fixed contact parameters (the contact conditions make
  // the derivative in the contact parameters vanish). A yaw rate turns the offset about the
  // vertical, a roll rate about the yawed z axis.
  const Vec3 d_yaw = cross(kVertical, c.offset);
  const Vec3 d_roll = cross(attitude.roll_axis(), c.offset);
  const double g1 = c.rail.slope;
  c.constraint_row[0] = g1;
  c.constraint_row[1] = -1.0;
  c.constraint_row[2] = 0.0;
  c.constraint_row[3] = g1 * d_yaw.x - d_yaw.y;
  c.constraint_row[4] = g1 * d_roll.x - d_roll.y;
  return IvpWheelsetResidualStatus::kOk;
}

// Normal forces [N] from the multipliers: the constraint forces' lateral and vertical resultants are
// carried by the two normals (-side sin delta, cos delta) in the cross-section.
bool normal_forces(const WheelContact& left, const WheelContact& right, double lambda_left, double lambda_right,
                   double& n_left, double& n_right) {
  const double lateral = left.constraint_row[0] * lambda_left + right.constraint_row[0] * lambda_right;
  const double vertical = left.constraint_row[1] * lambda_left + right.constraint_row[1] * lambda_right;
  const double sl = std::sin(left.contact_angle);
  const double cl = std::cos(left.contact_angle);
  const double sr = std::sin(right.contact_angle);
  const double cr = std::cos(right.contact_angle);
  // [-sl  sr] [N_L]   [lateral ]
  // [ cl  cr] [N_R] = [vertical]
  const double det = -sl * cr - sr * cl;
  if (std::abs(det) < kMinNormalDeterminant) return false;
  n_left = (cr * lateral - sr * vertical) / det;
  n_right = (-cl * lateral - sl * vertical) / det;
  return true;
}

// Creep force on the wheel [N], frame coordinates, by the test set's smooth saturation of Kalker's
// linear law (after Jaschinski): T = -mu N tanh(G c^2 C nu / (mu N)), bounded by mu N in magnitude.
Vec3 creep_force(const IvpWheelsetParameters& p, const double* y, const WheelContact& c, double normal_force) {
  // Contact-ellipse size c = sqrt(a b) from the curvatures (wheel's rolling radius, rail's profile).
  const double wheel_slope2 = 1.0 + c.wheel.slope * c.wheel.slope;
  const double rail_slope2 = 1.0 + c.rail.slope * c.rail.slope;
  const double rolling_curvature = 0.5 / (c.wheel.value * std::sqrt(wheel_slope2));
  const double lateral_curvature = 0.5 * (-c.rail.second_derivative / std::pow(rail_slope2, 1.5) +
                                          c.wheel.second_derivative / std::pow(wheel_slope2, 1.5));
  const double size = std::cbrt(3.0 * std::abs(normal_force) * (1.0 - p.poisson) * p.hertz_coefficient_e /
                                (2.0 * kTestSetPi * (rolling_curvature + lateral_curvature) * p.shear_modulus *
                                 std::sqrt(p.hertz_coefficient_g)));

  // The test set's creep kinematics: the yaw seen in the inclined contact plane is theta / cos(delta).
  const double sd = std::sin(c.contact_angle);
  const double cd = std::cos(c.contact_angle);
  const Attitude contact_attitude(y[kIvpYaw] / cd, y[kIvpRoll]);
  const Vec3 offset = contact_attitude.to_frame(c.body_point);
  const double spin = p.speed / p.nominal_radius + y[kIvpSpinRate];
  const Vec3 omega = spin * contact_attitude.axle() + y[kIvpYawRate] * kVertical +
                     y[kIvpRollRate] * contact_attitude.roll_axis();
  const Vec3 centre_velocity{y[kIvpLateralRate], y[kIvpVerticalRate], p.speed + y[kIvpLongitudinalRate]};
  const Vec3 turning = cross(omega, offset);
  const Vec3 slip_velocity = centre_velocity + turning;              // wheel material over the rail
  const double rolling_speed = 0.5 * norm(turning - centre_velocity);

  const Vec3 t_rolling = contact_attitude.roll_axis();
  const Vec3 t_lateral{contact_attitude.cos_yaw * cd, c.side * sd, -contact_attitude.sin_yaw * cd};
  const double nu_x = dot(t_rolling, slip_velocity) / rolling_speed;
  const double nu_y = dot(t_lateral, slip_velocity) / rolling_speed;
  const double nu_spin = (-c.side * sd * spin + cd * y[kIvpYawRate]) / rolling_speed;

  const double bound = p.friction * normal_force;
  const double gc2 = p.shear_modulus * size * size;
  double tx = -bound * std::tanh(gc2 * p.kalker_c11 * nu_x / bound);
  double ty = -bound * std::tanh((gc2 * p.kalker_c22 * nu_y + gc2 * size * p.kalker_c23 * nu_spin) / bound);
  const double magnitude = std::sqrt(tx * tx + ty * ty);
  if (magnitude * magnitude > bound * bound) {
    tx *= std::abs(bound) / magnitude;
    ty *= std::abs(bound) / magnitude;
  }
  return tx * t_rolling + ty * t_lateral;
}

struct Evaluation {
  WheelContact left;
  WheelContact right;
  double normal_left = 0;
  double normal_right = 0;
};

IvpWheelsetResidualStatus evaluate_contacts(const IvpWheelsetParameters& p, const double* y, Evaluation& e) {
  const Attitude attitude(y[kIvpYaw], y[kIvpRoll]);
  IvpWheelsetResidualStatus s =
      evaluate_wheel(p, y, +1.0, y[kIvpLeftContactXi], y[kIvpLeftContactAngle], attitude, e.left);
  if (s != IvpWheelsetResidualStatus::kOk) return s;
  s = evaluate_wheel(p, y, -1.0, y[kIvpRightContactXi], y[kIvpRightContactAngle], attitude, e.right);
  if (s != IvpWheelsetResidualStatus::kOk) return s;
  if (!normal_forces(e.left, e.right, kIvpMultiplierScale * y[kIvpLeftMultiplier],
                     kIvpMultiplierScale * y[kIvpRightMultiplier], e.normal_left, e.normal_right)) {
    return IvpWheelsetResidualStatus::kSingularContactAngles;
  }
  return IvpWheelsetResidualStatus::kOk;
}

double velocity_constraint(const WheelContact& c, const double* y) {
  double rate = 0.0;
  for (int i = 0; i < 5; ++i) rate += c.constraint_row[i] * y[kIvpLateralRate + i];
  return rate;
}

IvpWheelsetResidualStatus residual_into(const IvpWheelsetParameters& p, const double* y, const double* yp,
                                        double* residual) {
  Evaluation e;
  const IvpWheelsetResidualStatus status = evaluate_contacts(p, y, e);
  if (status != IvpWheelsetResidualStatus::kOk) return status;

  const Vec3 creep_left = creep_force(p, y, e.left, e.normal_left);
  const Vec3 creep_right = creep_force(p, y, e.right, e.normal_right);
  const double lambda_left = kIvpMultiplierScale * y[kIvpLeftMultiplier];
  const double lambda_right = kIvpMultiplierScale * y[kIvpRightMultiplier];
  const auto constraint_force = [&](int i) {
    return e.left.constraint_row[i] * lambda_left + e.right.constraint_row[i] * lambda_right;
  };

  // Moments of the creep forces about the centre, on the body's vertical, roll and spin axes.
  const Attitude attitude(y[kIvpYaw], y[kIvpRoll]);
  const Vec3 creep_moment = cross(e.left.offset, creep_left) + cross(e.right.offset, creep_right);

  const double roll = y[kIvpRoll];
  const double sin_roll = std::sin(roll);
  const double cos_roll = std::cos(roll);
  const double yaw_rate = y[kIvpYawRate];
  const double roll_rate = y[kIvpRollRate];
  const double spin = p.speed / p.nominal_radius + y[kIvpSpinRate];
  const double i_spin = p.spin_inertia;
  const double i_yaw = p.yaw_roll_inertia;
  // Suspension: lateral and longitudinal springs to the frame; the longitudinal pair resists yaw.
  const double yaw_restraint = -2.0 * p.spring_half_distance * p.spring_half_distance *
                               p.longitudinal_stiffness * y[kIvpYaw];

  const double force_x = creep_left.x + creep_right.x + constraint_force(0) -
                         2.0 * p.lateral_stiffness * y[kIvpLateral];
  const double force_y = creep_left.y + creep_right.y + constraint_force(1) - (p.mass + p.carried_mass) * p.gravity;
  const double force_z = creep_left.z + creep_right.z + constraint_force(2) -
                         2.0 * p.longitudinal_stiffness * y[kIvpLongitudinal];
  const double moment_yaw = i_yaw * yaw_rate * roll_rate * sin_roll - i_spin * spin * roll_rate -
                            (i_spin - i_yaw) * yaw_rate * sin_roll * roll_rate +
                            dot(creep_moment, attitude.body_vertical()) + cos_roll * yaw_restraint +
                            constraint_force(3);
  const double moment_roll = i_spin * spin * yaw_rate * cos_roll +
                             (i_spin - i_yaw) * yaw_rate * sin_roll * yaw_rate * cos_roll +
                             dot(creep_moment, attitude.roll_axis()) + constraint_force(4);
  const double moment_spin = -i_spin * yaw_rate * roll_rate * cos_roll + dot(creep_moment, attitude.axle()) +
                             sin_roll * yaw_restraint;

  for (int i = 0; i < 5; ++i) residual[i] = yp[i] - y[kIvpLateralRate + i];
  residual[5] = p.mass * yp[kIvpLateralRate] - force_x;
  residual[6] = p.mass * yp[kIvpVerticalRate] - force_y;
  residual[7] = p.mass * yp[kIvpLongitudinalRate] - force_z;
  residual[8] = i_yaw * cos_roll * yp[kIvpYawRate] - moment_yaw;
  residual[9] = i_yaw * yp[kIvpRollRate] - moment_roll;
  residual[10] = i_spin * (sin_roll * yp[kIvpYawRate] + yp[kIvpSpinRate]) - moment_spin;
  residual[11] = e.left.normal_rail_tangent;
  residual[12] = e.left.normal_rolling;
  residual[13] = e.right.normal_rail_tangent;
  residual[14] = e.right.normal_rolling;
  residual[15] = velocity_constraint(e.left, y);
  residual[16] = velocity_constraint(e.right, y);
  return IvpWheelsetResidualStatus::kOk;
}

// ---------------------------------------------------------------------------------------------
// IDA glue (the RAII owners and the flag check are core/dynamics/sundials_support.hpp's).

std::string flag_name(long flag) {
  char* name = IDAGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
  std::string result = name != nullptr ? name : "unknown";
  std::free(name);
  return result;
}

void copy_from(const double* data, IvpWheelsetVector& to) { std::copy(data, data + kIvpWheelsetDimension, to.begin()); }

struct ResidualData {
  const IvpWheelsetParameters* parameters = nullptr;
  IvpWheelsetResidualStatus last_failure = IvpWheelsetResidualStatus::kOk;
};

int ida_residual(sunrealtype, N_Vector yy, N_Vector yp, N_Vector rr, void* user_data) {
  auto* data = static_cast<ResidualData*>(user_data);
  const IvpWheelsetResidualStatus status =
      residual_into(*data->parameters, N_VGetArrayPointer(yy), N_VGetArrayPointer(yp), N_VGetArrayPointer(rr));
  if (status == IvpWheelsetResidualStatus::kOk) return 0;
  data->last_failure = status;
  return 1;  // recoverable: IDA retries with a smaller step
}

RunCounters read_counters(void* mem) {
  RunCounters c;
  check_sundials(IDAGetNumSteps(mem, &c.steps), "IDAGetNumSteps");
  check_sundials(IDAGetNumResEvals(mem, &c.residual_evals), "IDAGetNumResEvals");
  check_sundials(IDAGetNumLinResEvals(mem, &c.jacobian_residual_evals), "IDAGetNumLinResEvals");
  check_sundials(IDAGetNumJacEvals(mem, &c.jacobian_evals), "IDAGetNumJacEvals");
  check_sundials(IDAGetNumLinSolvSetups(mem, &c.lin_setups), "IDAGetNumLinSolvSetups");
  check_sundials(IDAGetNumErrTestFails(mem, &c.err_test_fails), "IDAGetNumErrTestFails");
  check_sundials(IDAGetNumNonlinSolvIters(mem, &c.nonlin_iters), "IDAGetNumNonlinSolvIters");
  check_sundials(IDAGetNumNonlinSolvConvFails(mem, &c.nonlin_conv_fails), "IDAGetNumNonlinSolvConvFails");
  check_sundials(IDAGetLastOrder(mem, &c.last_order), "IDAGetLastOrder");
  sunrealtype h = 0;
  check_sundials(IDAGetLastStep(mem, &h), "IDAGetLastStep");
  c.last_step = h;
  return c;
}

[[noreturn]] void fail_invalid(const std::string& what) { throw std::invalid_argument("ivp wheelset: " + what); }

}  // namespace

const char* to_string(IvpWheelsetResidualStatus status) {
  switch (status) {
    case IvpWheelsetResidualStatus::kOk: return "ok";
    case IvpWheelsetResidualStatus::kOffWheelProfile: return "contact point off the wheel profile (derailment)";
    case IvpWheelsetResidualStatus::kOffRailProfile: return "contact point off the rail profile (derailment)";
    case IvpWheelsetResidualStatus::kSingularContactAngles: return "contact normals parallel (normal forces undefined)";
  }
  return "unknown status";
}

IvpWheelsetState ivp_wheelset_initial_state() {
  IvpWheelsetState s;
  s.t = 0.0;
  s.y = {1.4941e-3, 4.0089e-7, 1.1241e-6, -2.8573e-4, 2.6459e-4,  // positions
         0.0, 0.0, 0.0, 0.0, 0.0,                                 // velocities
         0.0,                                                     // spin-rate perturbation
         -7.4122380357667139e-6, -0.1521364296121248,             // right wheel: psi, xi
         7.5634406395172940e-6, 0.1490635714733819,               // left wheel: psi, xi
         -8.3593e-3, -7.4144e-3};                                 // multipliers / 1e4
  s.yp = {0.0, 0.0, 0.0, 0.0, 0.0,
          -1.975258894011285, -1.0898297102811276e-3, 7.8855083626142589e-2,
          -5.533362821731549, -0.3487021489546511, -2.132968724380927,
          0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  return s;
}

IvpWheelsetVector ivp_wheelset_reference_solution() {
  return {0.86355386965811e-02, 0.13038281022727e-04, -0.93635784016818e-04, -0.13642299804033e-01,
          0.15292895005422e-02, -0.76985374142666e-01, -0.25151106429207e-03, 0.20541188079539e-02,
          -0.23904837703692e+00, -0.13633468454173e-01, -0.24421377661131e+00, -0.33666751972196e-03,
          -0.15949425684022e+00, 0.37839614386969e-03, 0.14173214964613e+00, -0.10124044903201e-01,
          -0.56285630573753e-02};
}

IvpWheelsetResidualStatus ivp_wheelset_residual(const IvpWheelsetParameters& parameters, const IvpWheelsetVector& y,
                                                const IvpWheelsetVector& yp, IvpWheelsetVector& residual) {
  IvpWheelsetVector out{};
  const IvpWheelsetResidualStatus status = residual_into(parameters, y.data(), yp.data(), out.data());
  if (status == IvpWheelsetResidualStatus::kOk) residual = out;
  return status;
}

IvpWheelsetContactState ivp_wheelset_contact_state(const IvpWheelsetParameters& parameters,
                                                   const IvpWheelsetVector& y) {
  Evaluation e;
  const IvpWheelsetResidualStatus status = evaluate_contacts(parameters, y.data(), e);
  if (status != IvpWheelsetResidualStatus::kOk) {
    throw std::runtime_error(std::string("ivp wheelset: contact state not evaluable: ") + to_string(status));
  }
  IvpWheelsetContactState s;
  const WheelContact* wheels[2] = {&e.left, &e.right};
  for (int w = 0; w < 2; ++w) {
    s.gap[w] = wheels[w]->gap;
    s.gap_rate[w] = velocity_constraint(*wheels[w], y.data());
    s.normal_rail_tangent[w] = wheels[w]->normal_rail_tangent;
    s.normal_rolling[w] = wheels[w]->normal_rolling;
    s.contact_angle[w] = wheels[w]->contact_angle;
  }
  s.normal_force = {e.normal_left, e.normal_right};
  return s;
}

IvpWheelsetRun integrate_ivp_wheelset(const IvpWheelsetParameters& parameters, const IvpWheelsetState& initial,
                                      double t_end, const IvpWheelsetIntegratorOptions& options,
                                      const IvpWheelsetStepObserver& observer) {
  if (!(options.relative_tolerance > 0.0) || !(options.absolute_tolerance > 0.0)) {
    std::ostringstream msg;
    msg << "tolerances must be positive (rtol = " << options.relative_tolerance
        << ", atol = " << options.absolute_tolerance << ")";
    fail_invalid(msg.str());
  }
  if (!(t_end > initial.t) || !std::isfinite(t_end)) {
    std::ostringstream msg;
    msg << "t_end = " << t_end << " s must be finite and after the initial time " << initial.t << " s";
    fail_invalid(msg.str());
  }
  if (options.max_steps <= 0) fail_invalid("max_steps must be positive");
  {
    IvpWheelsetVector r{};
    const IvpWheelsetResidualStatus status = ivp_wheelset_residual(parameters, initial.y, initial.yp, r);
    if (status != IvpWheelsetResidualStatus::kOk) {
      fail_invalid(std::string("initial state not evaluable: ") + to_string(status));
    }
    for (int i = 0; i < kIvpWheelsetDimension; ++i) {
      if (!(std::abs(r[i]) <= kMaxInitialResidual)) {
        std::ostringstream msg;
        msg << "initial state inconsistent: residual row " << i << " = " << r[i] << " (limit "
            << kMaxInitialResidual << ")";
        fail_invalid(msg.str());
      }
    }
  }

  const SundialsContext ctx;
  const SerialVector yy(kIvpWheelsetDimension, ctx.get());
  const SerialVector yp(kIvpWheelsetDimension, ctx.get());
  const SerialVector id(kIvpWheelsetDimension, ctx.get());
  const SerialVector atol(kIvpWheelsetDimension, ctx.get());
  std::copy(initial.y.begin(), initial.y.end(), yy.data());
  std::copy(initial.yp.begin(), initial.yp.end(), yp.data());
  for (int i = 0; i < kIvpWheelsetDimension; ++i) {
    id.data()[i] = i <= kIvpSpinRate ? 1.0 : 0.0;  // positions, velocities, spin rate are differential
    atol.data()[i] = options.absolute_tolerance;
  }
  if (!options.suppress_algebraic_error_test) {
    atol.data()[kIvpLeftMultiplier] = 1e10;
    atol.data()[kIvpRightMultiplier] = 1e10;
  }

  ResidualData data;
  data.parameters = &parameters;
  IdaSolver ida;  // IDACreate, IDAInit and the dense linear solver (difference-quotient Jacobian)
  ida.create(ctx.get(), ida_residual, initial.t, yy.get(), yp.get());
  void* mem = ida.mem();
  check_sundials(IDASVtolerances(mem, options.relative_tolerance, atol.get()), "IDASVtolerances");
  check_sundials(IDASetUserData(mem, &data), "IDASetUserData");
  check_sundials(IDASetId(mem, id.get()), "IDASetId");
  check_sundials(IDASetSuppressAlg(mem, options.suppress_algebraic_error_test ? SUNTRUE : SUNFALSE),
                 "IDASetSuppressAlg");
  check_sundials(IDASetMaxNumSteps(mem, options.max_steps), "IDASetMaxNumSteps");
  check_sundials(IDASetStopTime(mem, t_end), "IDASetStopTime");

  IvpWheelsetState state = initial;
  sunrealtype t = initial.t;
  for (long step = 0;; ++step) {
    if (step >= options.max_steps) {
      std::ostringstream msg;
      msg << "ivp wheelset: " << options.max_steps << " steps reached at t = " << t << " s before t_end = "
          << t_end << " s";
      throw std::runtime_error(msg.str());
    }
    const int flag = IDASolve(mem, t_end, &t, yy.get(), yp.get(), IDA_ONE_STEP);
    if (flag < 0) {
      std::ostringstream msg;
      msg << "IDASolve failed with flag " << flag << " (" << flag_name(flag) << ") at t = " << t << " s";
      if (data.last_failure != IvpWheelsetResidualStatus::kOk) {
        msg << "; last residual failure: " << to_string(data.last_failure);
      }
      throw std::runtime_error(msg.str());
    }
    state.t = t;
    copy_from(yy.data(), state.y);
    copy_from(yp.data(), state.yp);
    if (observer) observer(state);
    if (flag == IDA_TSTOP_RETURN || t >= t_end) break;
  }

  IvpWheelsetRun run;
  run.final_state = state;
  run.counters = read_counters(mem);
  return run;
}

}  // namespace wrc
