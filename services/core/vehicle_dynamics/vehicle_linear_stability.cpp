// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_linear_stability.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "core/dynamics/critical_speed_search.hpp"
#include "core/dynamics/wheelset_contact.hpp"
#include "core/numerics/number_text.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"

namespace wrc {
namespace {

// [1/s] generalised eigenvalues beyond this are the constraints' infinite ones: QZ leaves them at
// 1e12 and more (beta at rounding level), while the physical ones stay below 1e5 (the spin's
// creep damping 2 f11 r0^2 / (I_yy V), 4e4 1/s at 1 m/s).
constexpr double kInfiniteEigenvalue = 1e8;

// Per kind, the kinetic energy (times 2, for a unit of the mode's amplitude) of body b in the
// eigenvector x, and the body's total.
struct EnergyShares {
  double lateral = 0, vertical_roll = 0, vertical_pitch = 0, spin = 0;
  double total() const { return lateral + vertical_roll + vertical_pitch + spin; }
};

EnergyShares body_energy(const VehicleEquations& e, const VehicleLayout& layout, size_t b,
                         const Eigen::VectorXcd& x) {
  EnergyShares s;
  const Eigen::Index off = layout.offset[b];
  const int w = e.wheelset_of_body(b);
  const auto sq = [&x](Eigen::Index i) { return std::norm(x[i]); };
  if (w < 0) {
    const VehicleBody& body = e.vehicle().bodies[b];
    const Eigen::Index v = off + static_cast<Eigen::Index>(kBodyCoordinates);
    s.lateral = body.mass * sq(v + kBodyLateral) + body.inertia[2] * sq(v + kBodyYaw);
    s.vertical_roll = body.inertia[0] * sq(v + kBodyRoll);
    s.vertical_pitch = body.mass * sq(v + kBodyVertical) + body.inertia[1] * sq(v + kBodyPitch);
    return s;
  }
  const WheelsetParameters& p = e.wheelset(static_cast<size_t>(w)).parameters();
  s.lateral = p.mass * sq(off + kUnknownYDot) + p.yaw_inertia * sq(off + kUnknownYawDot);
  s.vertical_roll = p.mass * sq(off + kUnknownZDot) + p.roll_inertia * sq(off + kUnknownRollDot);
  s.spin = p.spin_inertia * sq(off + kUnknownSpinRate);
  return s;
}

VehicleMode classify(const VehicleEquations& e, const VehicleLayout& layout, std::complex<double> lambda,
                     const Eigen::VectorXcd& x) {
  VehicleMode m;
  m.eigenvalue = lambda;
  EnergyShares all;
  double total = 0.0, largest = -1.0;
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    const EnergyShares s = body_energy(e, layout, b, x);
    all.lateral += s.lateral;
    all.vertical_roll += s.vertical_roll;
    all.vertical_pitch += s.vertical_pitch;
    all.spin += s.spin;
    total += s.total();
    if (s.total() > largest) {
      largest = s.total();
      m.body = b;
    }
  }
  m.body_share = total > 0.0 ? largest / total : 0.0;
  const double most = std::max({all.lateral, all.vertical_roll, all.vertical_pitch, all.spin});
  m.kind = most == all.lateral         ? ModeKind::kLateralYaw
           : most == all.vertical_roll ? ModeKind::kVerticalRoll
           : most == all.vertical_pitch ? ModeKind::kVerticalPitch
                                        : ModeKind::kSpin;
  return m;
}

void refuse(const std::string& what) { throw std::invalid_argument("vehicle stability: " + what); }

}  // namespace

double VehicleMode::frequency() const { return std::abs(eigenvalue.imag()) / (2.0 * M_PI); }

double VehicleMode::damping_ratio() const {
  const double magnitude = std::abs(eigenvalue);
  return magnitude > 0.0 ? -eigenvalue.real() / magnitude : 0.0;
}

const VehicleMode& LinearisedVehicle::least_damped() const {
  if (modes.empty()) throw std::logic_error("LinearisedVehicle: no modes");
  return modes.front();
}

VehicleLinearStability::VehicleLinearStability(VehicleRunSpec spec, std::shared_ptr<ContactEvaluator> contact,
                                               double nominal_radius)
    : spec_(std::move(spec)), contact_(std::move(contact)), nominal_radius_(nominal_radius) {
  validate(spec_.vehicle);
  spec_.run.validate();
  if (!contact_) refuse("no contact evaluator");
  if (!(nominal_radius > 0.0) || !std::isfinite(nominal_radius))
    refuse("nominal radius " + number_text(nominal_radius) + " m must be finite and > 0");
  if (!spec_.run.track.straight() || !spec_.run.irregularity.empty())
    refuse("the analysis is on straight, level track without irregularities");
  const InitialState& i = spec_.run.initial;
  if (i.y != 0.0 || i.yaw != 0.0 || i.y_dot != 0.0 || i.yaw_dot != 0.0 || i.spin_rate_offset != 0.0)
    refuse("the initial state must be the rest state (every initial value 0)");
  for (const VehicleBody& b : spec_.vehicle.bodies)
    if (b.external_force[1] != 0.0)
      refuse("body '" + b.name + "': external_force: a lateral force " + number_text(b.external_force[1]) +
             " N leaves no centred rest state");
  // What the equations refuse (a wheelset they cannot take, an axle off the wheel's radius), now.
  try {
    VehicleEquations(spec_.vehicle, spec_.run.wheelset, TrackLayout{}, TrackIrregularity{}, nominal_radius_,
                     static_wheel_loads(spec_.vehicle, spec_.run.wheelset.gravity));
  } catch (const std::invalid_argument& e) {
    refuse(e.what());
  }
}

LinearisedVehicle VehicleLinearStability::linearise(double speed) {
  if (!std::isfinite(speed) || !(speed > 0.0)) refuse("speed " + number_text(speed) + " m/s must be finite and > 0");
  WheelsetParameters common = spec_.run.wheelset;
  common.speed = speed;
  const std::vector<double> loads = static_wheel_loads(spec_.vehicle, common.gravity);
  VehicleEquations equations(spec_.vehicle, common, TrackLayout{}, TrackIrregularity{}, nominal_radius_, loads);
  VehicleContact contact(contact_, equations, false);
  VehicleDae dae(equations, contact);
  const ContactFormulation own = formulation_of(*contact_);
  const IntegratorSettings& s = spec_.run.integrator;
  LinearisedVehicle l;
  l.speed = speed;
  l.rest_state = vehicle_rest_state(dae, own, 0.0, s.position_tolerance, s.velocity_tolerance);
  const VehicleLayout layout = dae.layout();
  const Eigen::Index n = layout.unknowns;
  const std::vector<double> zero(static_cast<size_t>(n), 0.0);
  Eigen::VectorXd r(n);
  dae.residual(0.0, l.rest_state.data(), zero.data(), r.data());
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n, n), e = Eigen::MatrixXd::Zero(n, n);
  dae.jacobian(0.0, 0.0, l.rest_state.data(), zero.data(), r.data(), DenseMatrixView{j.data(), n});
  equations.add_derivative_terms(layout, l.rest_state.data(), 1.0, DenseMatrixView{e.data(), n});
  if (own == ContactFormulation::kElastic) {
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(-e.partialPivLu().solve(j));
    if (solver.info() != Eigen::Success) throw std::runtime_error("vehicle stability: the eigenvalues did not converge");
    for (Eigen::Index k = 0; k < n; ++k)
      l.modes.push_back(classify(equations, layout, solver.eigenvalues()[k], solver.eigenvectors().col(k)));
  } else {
    const Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> solver(-j, e, true);
    if (solver.info() != Eigen::Success) throw std::runtime_error("vehicle stability: QZ did not converge");
    for (Eigen::Index k = 0; k < n; ++k) {
      const double beta = solver.betas()[k];
      if (beta == 0.0) continue;
      const std::complex<double> lambda = solver.alphas()[k] / beta;
      if (!(std::abs(lambda) < kInfiniteEigenvalue)) continue;
      l.modes.push_back(classify(equations, layout, lambda, solver.eigenvectors().col(k)));
    }
    // A car body or frame keeps its 10 states, a wheelset in rigid contact y, yaw, their rates and
    // the spin.
    const size_t wheelsets = equations.wheelset_count();
    const size_t expected = kBodyUnknowns * (equations.vehicle().bodies.size() - wheelsets) + 5 * wheelsets;
    if (l.modes.size() != expected) {
      std::ostringstream msg;
      msg << "vehicle stability at " << speed << " m/s: " << l.modes.size() << " finite eigenvalues where the rigid "
          << "contact's constraints leave " << expected;
      throw std::runtime_error(msg.str());
    }
  }
  std::sort(l.modes.begin(), l.modes.end(), [](const VehicleMode& a, const VehicleMode& b) {
    if (a.eigenvalue.real() != b.eigenvalue.real()) return a.eigenvalue.real() > b.eigenvalue.real();
    return a.eigenvalue.imag() > b.eigenvalue.imag();
  });
  return l;
}

VehicleCriticalSpeed VehicleLinearStability::critical_speed(const std::vector<LinearisedVehicle>& scan,
                                                            double relative_tolerance) {
  const GrowthCrossing<LinearisedVehicle> crossing = first_growth_crossing(
      scan, [this](double v) { return linearise(v); },
      [](const LinearisedVehicle& l) { return l.least_damped().eigenvalue.real(); }, relative_tolerance);
  VehicleCriticalSpeed c;
  c.linearisations = crossing.linearisations;
  if (!crossing.found) return c;
  c.found = true;
  c.speed = crossing.speed;
  c.mode = crossing.at.least_damped();
  return c;
}

}  // namespace wrc
