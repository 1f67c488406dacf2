// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/linear_stability.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/critical_speed_search.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/numerics/inclusive_range.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

// Central-difference increments of the unknowns about the steady state. The truncation error
// goes with (h / L)^2, L the length over which the contact changes (a millimetre of the profiles,
// a creepage of 1e-3 before FASTSIM saturates); the rounding error with the contact's own noise
// over h (its potential-point roots are found to about 1e-12 m, which moves a rolling radius by
// the profile slope times that). 1e-6 keeps both small (estimated below 1e-5 relative; the
// tests' agreement with the closed form's coefficients, 0.2 to 0.6 %, bounds it from above).
constexpr double kPoseIncrement = 1e-6;          // [m, rad]
constexpr double kRateIncrement = 1e-6;          // [m/s, rad/s]
constexpr double kRelativeSpinIncrement = 1e-7;  // [-] of the spin rate
constexpr double kScaledIncrement = 1e-6;        // normal forces [-] and GGL multipliers [m/s]
// The spin rate's Newton iteration stops when the axle moment is below this times force_scale x 1 m.
constexpr double kSpinTolerance = 1e-11;
constexpr int kMaxSpinIterations = 20;

void check_speed(double speed) {
  if (!(std::isfinite(speed) && speed > 0.0))
    throw std::invalid_argument("linear stability: speed " + number_text(speed) + " m/s must be finite and > 0");
}

double increment(int k, double value) {
  if (k < kPoseUnknowns) return kPoseIncrement;
  if (k < kUnknownSpinRate) return kRateIncrement;
  if (k == kUnknownSpinRate) return kRelativeSpinIncrement * std::max(std::abs(value), 1.0);
  return kScaledIncrement;
}

// The equations, contact and initialisation context of one speed.
struct Evaluation {
  Evaluation(const WheelsetParameters& p, double r0, ContactEvaluator& contact, ContactFormulation f)
      : equations(p, r0, r0), evaluator(contact), formulation(f) {}
  WheelsetEquations equations;
  ContactEvaluator& evaluator;
  ContactFormulation formulation;
  FollowedBranches branches;  // the model's own (lowest) points: the centred wheelset is on its tread
  ContactResult last;

  ContactResult evaluate(ContactFormulation f, const double* y) {
    return evaluator.evaluate({equations.query(f, y, branches)}).front();
  }
  InitialisationContext context(ContactFormulation f) {
    return InitialisationContext{equations, f, branches,
                                 [this, f](const double* y) -> const ContactResult& {
                                   last = evaluate(f, y);
                                   return last;
                                 },
                                 [this](const std::vector<ContactQuery>& batch) { return evaluator.evaluate(batch); },
                                 {}};
  }
};

// Kinetic energy of a mode's velocities in each group: (lateral-yaw, vertical-roll, spin).
ModeKind classify(const Eigen::Vector4cd& v, std::complex<double> spin, const WheelsetParameters& p) {
  const double lateral = p.mass * std::norm(v[0]) + p.yaw_inertia * std::norm(v[3]);
  const double vertical = p.mass * std::norm(v[1]) + p.roll_inertia * std::norm(v[2]);
  const double rotation = p.spin_inertia * std::norm(spin);
  if (rotation >= lateral && rotation >= vertical) return ModeKind::kSpin;
  return vertical > lateral ? ModeKind::kVerticalRoll : ModeKind::kLateralYaw;
}

// dF/dy (jy) by central differences about x0, every perturbed state in one batch; dF/dy' (jyp)
// the same way with the contact of the steady state (the residual is linear in y', so this is exact).
void difference_jacobians(Evaluation& e, ContactFormulation f, const std::vector<double>& x0,
                          const ContactResult& steady_contact, Eigen::MatrixXd& jy, Eigen::MatrixXd& jyp) {
  const int n = static_cast<int>(x0.size());
  std::vector<ContactQuery> batch;
  std::vector<double> h(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    h[static_cast<size_t>(k)] = increment(k, x0[static_cast<size_t>(k)]);
    for (int sign : {1, -1}) {
      std::vector<double> x = x0;
      x[static_cast<size_t>(k)] += sign * h[static_cast<size_t>(k)];
      batch.push_back(e.equations.query(f, x.data(), e.branches));
    }
  }
  const std::vector<ContactResult> results = e.evaluator.evaluate(batch);
  jy.resize(n, n);
  jyp.resize(n, n);
  std::vector<double> zero(static_cast<size_t>(n), 0.0), plus(static_cast<size_t>(n)), minus(static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double hk = h[static_cast<size_t>(k)];
    std::vector<double> xp = x0, xm = x0;
    xp[static_cast<size_t>(k)] += hk;
    xm[static_cast<size_t>(k)] -= hk;
    e.equations.residual(f, xp.data(), zero.data(), results[static_cast<size_t>(2 * k)], e.branches, plus.data());
    e.equations.residual(f, xm.data(), zero.data(), results[static_cast<size_t>(2 * k + 1)], e.branches, minus.data());
    for (int i = 0; i < n; ++i) jy(i, k) = (plus[static_cast<size_t>(i)] - minus[static_cast<size_t>(i)]) / (2.0 * hk);
    std::vector<double> dp = zero, dm = zero;
    dp[static_cast<size_t>(k)] = 1.0;
    dm[static_cast<size_t>(k)] = -1.0;
    e.equations.residual(f, x0.data(), dp.data(), steady_contact, e.branches, plus.data());
    e.equations.residual(f, x0.data(), dm.data(), steady_contact, e.branches, minus.data());
    for (int i = 0; i < n; ++i) jyp(i, k) = (plus[static_cast<size_t>(i)] - minus[static_cast<size_t>(i)]) / 2.0;
  }
}

// The linearised DAE jyp dx' + jy dx = 0 reduced to x' = A x, with the states' names and the
// rows that give a state vector's coordinate velocities (4) and spin rate.
struct ReducedSystem {
  Eigen::MatrixXd a;
  std::vector<std::string> state_names;
  Eigen::MatrixXd velocity_of_state;
  Eigen::RowVectorXd spin_of_state;
};

// Elastic contact: every unknown is a state and jyp is diagonal.
ReducedSystem reduce_elastic(const Eigen::MatrixXd& jy, const Eigen::MatrixXd& jyp) {
  const int n = static_cast<int>(jy.rows());
  ReducedSystem r;
  r.a = -(jyp.diagonal().cwiseInverse().asDiagonal() * jy);
  r.state_names = {"y [m]",          "z [m]",         "roll [rad]",       "yaw [rad]",      "y_dot [m/s]",
                   "z_dot [m/s]",    "roll_dot [rad/s]", "yaw_dot [rad/s]", "spin_rate [rad/s]"};
  r.velocity_of_state = Eigen::MatrixXd::Zero(4, n);
  r.velocity_of_state.block(0, kPoseUnknowns, 4, 4).setIdentity();
  r.spin_of_state = Eigen::RowVectorXd::Zero(n);
  r.spin_of_state[kUnknownSpinRate] = 1.0;
  return r;
}

// Rigid contact: the states y, yaw, their rates and the spin rate on the constraints.
ReducedSystem reduce_rigid(const Eigen::MatrixXd& jy, const Eigen::MatrixXd& jyp) {
  ReducedSystem r;
  // G: the gap rows' derivatives by the pose. T: the pose changes that keep both gaps, with
  // y and yaw free (z and roll follow: their 2 x 2 block of G is the one the position projection
  // inverts).
  const Eigen::Matrix<double, 2, 4> g = jy.block(kUnknownNormalLeft, 0, 2, kPoseUnknowns);
  Eigen::Matrix2d dependent, independent;
  dependent << g(0, kUnknownZ), g(0, kUnknownRoll), g(1, kUnknownZ), g(1, kUnknownRoll);
  independent << g(0, kUnknownY), g(0, kUnknownYaw), g(1, kUnknownY), g(1, kUnknownYaw);
  const Eigen::Matrix2d follow = -dependent.fullPivLu().solve(independent);
  Eigen::Matrix<double, 4, 2> t = Eigen::Matrix<double, 4, 2>::Zero();
  t(kUnknownY, 0) = 1.0;
  t(kUnknownYaw, 1) = 1.0;
  t.row(kUnknownZ) = follow.row(0);
  t.row(kUnknownRoll) = follow.row(1);
  // The equations of motion on the constraints: M T w' + J_N dN = -(J_q T p + J_v T w + J_Omega dOmega),
  // four equations for w' (2) and dN (2); dmu = 0 (G dq' = G dv - G G^T dmu = 0 with G dv = 0).
  const int v0 = kPoseUnknowns;
  Eigen::Matrix4d k;
  k.leftCols(2) = jyp.block(v0, v0, 4, 4) * t;
  k.rightCols(2) = jy.block(v0, kUnknownNormalLeft, 4, 2);
  Eigen::Matrix<double, 4, 5> rhs;
  rhs.leftCols(2) = -jy.block(v0, 0, 4, 4) * t;
  rhs.middleCols(2, 2) = -jy.block(v0, v0, 4, 4) * t;
  rhs.col(4) = -jy.block(v0, kUnknownSpinRate, 4, 1);
  const Eigen::Matrix<double, 4, 5> solved = k.fullPivLu().solve(rhs);  // rows: w' (2), dN (2)
  Eigen::Matrix<double, 1, 5> spin;
  spin.leftCols(2) = jy.block(kUnknownSpinRate, 0, 1, 4) * t;
  spin.middleCols(2, 2) = jy.block(kUnknownSpinRate, v0, 1, 4) * t;
  spin(4) = jy(kUnknownSpinRate, kUnknownSpinRate);
  spin += jy.block(kUnknownSpinRate, kUnknownNormalLeft, 1, 2) * solved.bottomRows(2);
  r.a = Eigen::MatrixXd::Zero(5, 5);
  r.a(0, 2) = r.a(1, 3) = 1.0;
  r.a.block(2, 0, 2, 5) = solved.topRows(2);
  r.a.row(4) = -spin / jyp(kUnknownSpinRate, kUnknownSpinRate);
  r.state_names = {"y [m]", "yaw [rad]", "y_dot [m/s]", "yaw_dot [rad/s]", "spin_rate [rad/s]"};
  r.velocity_of_state = Eigen::MatrixXd::Zero(4, 5);
  r.velocity_of_state.block(0, 2, 4, 2) = t;
  r.spin_of_state = Eigen::RowVectorXd::Zero(5);
  r.spin_of_state[4] = 1.0;
  return r;
}

// The eigenvalues of the reduced system, each classified by its eigenvector, largest real part
// first (of a pair, the one with Im >= 0).
std::vector<StabilityMode> modes_of(const ReducedSystem& system, const WheelsetParameters& p, double speed) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(system.a, true);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("linear stability: the eigenvalues at " + number_text(speed) + " m/s did not converge");
  std::vector<StabilityMode> modes;
  for (int i = 0; i < system.a.rows(); ++i) {
    const Eigen::VectorXcd vector = solver.eigenvectors().col(i);
    const Eigen::Vector4cd velocity = system.velocity_of_state.cast<std::complex<double>>() * vector;
    const std::complex<double> spin_rate = (system.spin_of_state.cast<std::complex<double>>() * vector)(0);
    modes.push_back({solver.eigenvalues()[i], classify(velocity, spin_rate, p)});
  }
  std::sort(modes.begin(), modes.end(), [](const StabilityMode& l, const StabilityMode& r) {
    if (l.eigenvalue.real() != r.eigenvalue.real()) return l.eigenvalue.real() > r.eigenvalue.real();
    return l.eigenvalue.imag() > r.eigenvalue.imag();
  });
  return modes;
}

}  // namespace

const char* mode_kind_name(ModeKind kind) {
  switch (kind) {
    case ModeKind::kLateralYaw: return "lateral-yaw";
    case ModeKind::kVerticalRoll: return "vertical-roll";
    case ModeKind::kSpin: return "spin";
    case ModeKind::kVerticalPitch: return "vertical-pitch";
  }
  return "?";
}

double StabilityMode::frequency() const { return std::abs(eigenvalue.imag()) / (2.0 * M_PI); }

double StabilityMode::damping_ratio() const {
  const double magnitude = std::abs(eigenvalue);
  return magnitude > 0.0 ? -eigenvalue.real() / magnitude : 0.0;
}

const StabilityMode& LinearisedWheelset::least_damped() const {
  if (modes.empty()) throw std::logic_error("LinearisedWheelset: no modes");
  return modes.front();
}

std::vector<double> stability_speeds(double from, double to, double step) {
  const auto bad = [](const std::string& what) { throw std::invalid_argument("speed range: " + what); };
  if (!std::isfinite(from) || !(from > 0.0)) bad("the first speed " + number_text(from) + " m/s must be finite and > 0");
  if (!std::isfinite(to) || !(to >= from))
    bad("the last speed " + number_text(to) + " m/s must be finite and >= the first, " + number_text(from) + " m/s");
  if (!std::isfinite(step) || !(step > 0.0)) bad("the step " + number_text(step) + " m/s must be finite and > 0");
  const long count = inclusive_range_count(from, to, step);
  if (count > kMaxStabilitySpeeds)
    bad("the step " + number_text(step) + " m/s gives " + std::to_string(count) + " speeds, more than " +
        std::to_string(kMaxStabilitySpeeds));
  return inclusive_range(from, to, step);
}

LinearStability::LinearStability(WheelsetParameters parameters, std::shared_ptr<ContactEvaluator> contact,
                                 double nominal_radius)
    : parameters_(parameters), contact_(std::move(contact)), nominal_radius_(nominal_radius) {
  if (parameters_.lateral_force != 0.0)
    throw std::invalid_argument("linear stability: lateral_force " + number_text(parameters_.lateral_force) +
                                " N must be 0 (with a lateral load the wheelset has no centred steady state)");
  parameters_.validate();
  if (!contact_) throw std::invalid_argument("linear stability: no contact evaluator");
  if (!(std::isfinite(nominal_radius) && nominal_radius > 0.0))
    throw std::invalid_argument("linear stability: nominal radius " + number_text(nominal_radius) + " m must be > 0");
  formulation_ = contact_model_entry(contact_->model()).dynamics_formulation;
}

CentredSteadyState LinearStability::steady_state(double speed) {
  check_speed(speed);
  WheelsetParameters p = parameters_;
  p.speed = speed;
  const double r0 = nominal_radius_;
  Evaluation e(p, r0, *contact_, formulation_);
  // As a run starts (WheelsetSimulation::start): rigid contact of the centred wheelset, where the
  // vertical suspension is relaxed; elastic contact then settles on its Hertz springs.
  std::vector<double> y(static_cast<size_t>(kRigidUnknowns), 0.0);
  y[kUnknownZ] = r0;
  y[kUnknownSpinRate] = speed / r0;
  y[kUnknownNormalLeft] = y[kUnknownNormalRight] = 1.0;
  project_positions(e.context(ContactFormulation::kRigid), y);
  e.equations.set_z_reference(y[kUnknownZ]);
  const bool elastic = formulation_ == ContactFormulation::kElastic;
  if (elastic) y.resize(kElasticUnknowns);
  const InitialisationContext context = e.context(formulation_);
  std::vector<double> yp;
  // The spin rate at which the axle moment vanishes (Newton, the slope by a forward difference);
  // the rigid normal forces and the elastic height and roll follow each spin rate.
  const double inertia = p.spin_inertia;
  const double moment_tolerance = kSpinTolerance * e.equations.force_scale();
  auto axle_moment = [&](std::vector<double>& state) {
    if (elastic) settle_elastic(context, state, 0.0, 0.0);
    consistent_derivatives(context, state, yp);
    return inertia * yp[kUnknownSpinRate];
  };
  double moment = axle_moment(y);
  for (int iteration = 0; std::abs(moment) > moment_tolerance; ++iteration) {
    if (iteration == kMaxSpinIterations)
      throw std::runtime_error("linear stability: no spin rate balances the axle moment at " + number_text(speed) +
                               " m/s (left " + number_text(moment) + " N m)");
    std::vector<double> ahead = y;
    const double h = increment(kUnknownSpinRate, y[kUnknownSpinRate]);
    ahead[kUnknownSpinRate] += h;
    const double slope = (axle_moment(ahead) - moment) / h;
    if (!(slope < 0.0))
      throw std::runtime_error("linear stability: the axle moment does not fall with the spin rate at " +
                               number_text(speed) + " m/s");
    y[kUnknownSpinRate] -= moment / slope;
    moment = axle_moment(y);
  }
  CentredSteadyState s;
  s.speed = speed;
  s.state = y;
  s.contact = e.evaluate(formulation_, y.data());
  s.z_reference = e.equations.z_reference();
  std::vector<double> zero(y.size(), 0.0), r(y.size());
  e.equations.residual(formulation_, y.data(), zero.data(), s.contact, e.branches, r.data());
  for (int k = kPoseUnknowns; k <= kUnknownSpinRate; ++k)
    s.residual = std::max(s.residual, std::abs(r[static_cast<size_t>(k)]) / e.equations.force_scale());
  return s;
}

LinearisedWheelset LinearStability::linearise(double speed) {
  LinearisedWheelset out;
  out.speed = speed;
  out.steady = steady_state(speed);
  WheelsetParameters p = parameters_;
  p.speed = speed;
  Evaluation e(p, nominal_radius_, *contact_, formulation_);
  e.equations.set_z_reference(out.steady.z_reference);
  Eigen::MatrixXd jy, jyp;
  difference_jacobians(e, formulation_, out.steady.state, out.steady.contact, jy, jyp);
  const ReducedSystem reduced =
      formulation_ == ContactFormulation::kElastic ? reduce_elastic(jy, jyp) : reduce_rigid(jy, jyp);
  out.state_names = reduced.state_names;
  out.state_matrix = reduced.a;
  out.modes = modes_of(reduced, p, speed);
  return out;
}

CriticalSpeed LinearStability::critical_speed(const std::vector<LinearisedWheelset>& scan, double relative_tolerance) {
  const GrowthCrossing<LinearisedWheelset> crossing = first_growth_crossing(
      scan, [this](double v) { return linearise(v); },
      [](const LinearisedWheelset& l) { return l.least_damped().eigenvalue.real(); }, relative_tolerance);
  CriticalSpeed c;
  c.linearisations = crossing.linearisations;
  if (!crossing.found) return c;
  c.found = true;
  c.speed = crossing.speed;
  c.frequency = crossing.at.least_damped().frequency();
  c.kind = crossing.at.least_damped().kind;
  return c;
}

}  // namespace wrc
