// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/consistent_initialisation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>

namespace wrc {
namespace {

// [m] the position projection stops when every active gap is below this: far below the
// integrator's position tolerance, a few hundred ulps of the wheelset's height.
constexpr double kGapTolerance = 1e-13;
// [-] iterations of each position projection: Newton converges in a few from a state near contact;
// 40 leaves room for the start (height r0, far from the rigid one by the profile's shape).
constexpr int kMaxProjectionIterations = 40;

// [m] for the height, [rad] for the roll: the finite-difference increment of the settling's
// Jacobian (the Hertz force is smooth at that scale, rounding of the distance well below it).
constexpr double kSettleIncrement = 1e-9;
// [-] the settling stops when the force and moment mismatch is below this times the force scale
// (N per unit of the scaled normal forces) [N].
constexpr double kSettleTolerance = 1e-9;
// [-] Newton iterations of the settling, and step halvings per iteration (a step of 2^-30 of the
// Newton step that still does not lower the mismatch means there is no better point near).
constexpr int kMaxSettleIterations = 60;
constexpr int kMaxSettleHalvings = 30;

// [s] the time along the velocity over which the constraints' gradients are differenced for
// (dG/dt) v: small against any motion of the contact, large against the gradients' rounding.
constexpr double kGradientRateStep = 1e-7;
// [-] iterations of the rigid normal forces (the creep forces depend on them through Hertz), and
// the change of the scaled normal forces below which they stop [-].
constexpr int kMaxNormalForceIterations = 8;
constexpr double kNormalForceTolerance = 1e-10;

// The active constraints' gap gradients at c, one row each [-, -, m/rad, m/rad]; their gaps into
// gaps [m] and their gap rates (the rails moving under the wheelset) into rates [m/s] when given.
Eigen::MatrixXd constraint_gradients(const FollowedBranches& branches, const ContactResult& c, Eigen::VectorXd* gaps,
                                     Eigen::VectorXd* rates = nullptr) {
  const std::vector<ActiveConstraint> active = active_constraints(branches);
  const int count = static_cast<int>(active.size());
  Eigen::MatrixXd g(count, kPoseUnknowns);
  if (gaps) gaps->resize(count);
  if (rates) rates->resize(count);
  for (int r = 0; r < count; ++r) {
    const WheelConstraint& w = active[static_cast<size_t>(r)].of(c);
    g.row(r) = w.gap_gradient.transpose();
    if (gaps) (*gaps)[r] = w.gap;
    if (rates) (*rates)[r] = w.gap_rate;
  }
  return g;
}

}  // namespace

const WheelConstraint& ActiveConstraint::of(const ContactResult& c) const {
  return second ? c.second_wheels[static_cast<size_t>(wheel)].value() : c.wheels[static_cast<size_t>(wheel)];
}

std::vector<ActiveConstraint> active_constraints(const FollowedBranches& branches) {
  std::vector<ActiveConstraint> active = {{0, false, kUnknownNormalLeft}, {1, false, kUnknownNormalRight}};
  for (int i = 0; i < 2; ++i)
    if (branches.two_point(i)) active.push_back({i, true, kUnknownSecondNormalLeft + i});
  return active;
}

void project_positions(const InitialisationContext& context, std::vector<double>& y) {
  const FollowedBranches& branches = context.branches;
  for (int iteration = 0; iteration < kMaxProjectionIterations && branches.any_two_point(); ++iteration) {
    // Three or four constraints on the four coordinates: the smallest correction in the mass
    // metric (Gauss-Newton), dq = -M^-1 G^T (G M^-1 G^T)^-1 gap.
    Eigen::VectorXd gap;
    const Eigen::MatrixXd g = constraint_gradients(branches, context.contact_at(y.data()), &gap);
    if (gap.cwiseAbs().maxCoeff() < kGapTolerance) return;
    const Eigen::Vector4d inv_mass = context.equations.mass_diagonal().cwiseInverse();
    const Eigen::MatrixXd mg = inv_mass.asDiagonal() * g.transpose();
    const Eigen::VectorXd dq = -mg * (g * mg).fullPivLu().solve(gap);
    for (int k = 0; k < kPoseUnknowns; ++k) y[static_cast<size_t>(k)] += dq[k];
    if (iteration == kMaxProjectionIterations - 1)
      throw std::runtime_error("no rigid two-point contact: the position projection did not converge");
  }
  for (int iteration = 0; iteration < kMaxProjectionIterations; ++iteration) {
    const ContactResult& c = context.contact_at(y.data());
    const Eigen::Vector2d gap(c.wheels[0].gap, c.wheels[1].gap);
    if (gap.cwiseAbs().maxCoeff() < kGapTolerance) return;
    Eigen::Matrix2d j;
    for (int i = 0; i < 2; ++i) {
      j(i, 0) = c.wheels[static_cast<size_t>(i)].gap_gradient[kUnknownZ];
      j(i, 1) = c.wheels[static_cast<size_t>(i)].gap_gradient[kUnknownRoll];
    }
    const Eigen::Vector2d delta = j.fullPivLu().solve(-gap);
    y[kUnknownZ] += delta[0];
    y[kUnknownRoll] += delta[1];
  }
  std::ostringstream msg;
  msg << "no rigid contact of both wheels at y = " << y[kUnknownY] << " m, yaw = " << y[kUnknownYaw]
      << " rad: the height and roll iteration did not converge";
  throw std::runtime_error(msg.str());
}

void project_velocities(const InitialisationContext& context, std::vector<double>& y) {
  Eigen::VectorXd rates;
  const Eigen::MatrixXd g = constraint_gradients(context.branches, context.contact_at(y.data()), nullptr, &rates);
  const Eigen::Vector4d inv_mass = context.equations.mass_diagonal().cwiseInverse();
  Eigen::Vector4d v(y[kUnknownYDot], y[kUnknownZDot], y[kUnknownRollDot], y[kUnknownYawDot]);
  const Eigen::MatrixXd mg = inv_mass.asDiagonal() * g.transpose();
  // G v + gap_rate = 0 afterwards (the rails may move under the wheelset).
  const Eigen::VectorXd impulse = (g * mg).fullPivLu().solve(g * v + rates);
  v -= mg * impulse;  // the velocity change of an inelastic impact along the constraint normals
  for (int k = 0; k < 4; ++k) y[kPoseUnknowns + k] = v[k];
}

void settle_elastic(const InitialisationContext& context, std::vector<double>& y, double z_acceleration,
                    double roll_acceleration) {
  const WheelsetEquations& equations = context.equations;
  const Eigen::Vector4d m = equations.mass_diagonal();
  const double gyro = equations.parameters().spin_inertia * y[kUnknownSpinRate] * y[kUnknownYawDot];
  const Eigen::Vector2d target(m[1] * z_acceleration, m[2] * roll_acceleration - gyro);
  const double scale = equations.force_scale();
  auto mismatch = [&](const ContactResult& c, const std::vector<double>& state) {
    const Eigen::Vector4d q = equations.applied_forces(context.formulation, state.data(), c, nullptr);
    return Eigen::Vector2d(q[1] - target[0], q[2] - target[1]);
  };
  y[kUnknownZ] -= kElasticStartDepth;
  const double h = kSettleIncrement;
  for (int iteration = 0; iteration < kMaxSettleIterations; ++iteration) {
    std::vector<double> dz = y, droll = y;
    dz[kUnknownZ] += h;
    droll[kUnknownRoll] += h;
    std::vector<ContactResult> r = context.evaluate({equations.query(context.formulation, y.data(), context.branches),
                                                     equations.query(context.formulation, dz.data(), context.branches),
                                                     equations.query(context.formulation, droll.data(), context.branches)});
    const Eigen::Vector2d f = mismatch(r[0], y);
    if (f.norm() < kSettleTolerance * scale) return;
    Eigen::Matrix2d j;
    j.col(0) = (mismatch(r[1], dz) - f) / h;
    j.col(1) = (mismatch(r[2], droll) - f) / h;
    const Eigen::Vector2d delta = j.fullPivLu().solve(-f);
    double lambda = 1.0;
    for (int halving = 0; halving < kMaxSettleHalvings; ++halving, lambda *= 0.5) {
      std::vector<double> trial = y;
      trial[kUnknownZ] += lambda * delta[0];
      trial[kUnknownRoll] += lambda * delta[1];
      const ContactResult& c = context.contact_at(trial.data());
      if (mismatch(c, trial).norm() < f.norm()) {
        y = trial;
        break;
      }
    }
  }
  std::ostringstream msg;
  msg << "the elastic contact finds no height and roll that carry the wheelset at y = " << y[kUnknownY] << " m";
  throw std::runtime_error(msg.str());
}

void adapt_to_formulation(const InitialisationContext& context, ContactFormulation from, std::vector<double>& y,
                          const std::array<double, 2>& normal_forces, double z_acceleration,
                          double roll_acceleration) {
  if (context.formulation == ContactFormulation::kRigid) {
    if (from == ContactFormulation::kElastic) {
      y.resize(kRigidUnknowns, 0.0);
      y[kUnknownNormalLeft] = normal_forces[0] / context.equations.force_scale();
      y[kUnknownNormalRight] = normal_forces[1] / context.equations.force_scale();
    }
    project_positions(context, y);
    project_velocities(context, y);
  } else if (from == ContactFormulation::kRigid) {
    y.resize(kElasticUnknowns);
    settle_elastic(context, y, z_acceleration, roll_acceleration);
  }
}

void consistent_derivatives(const InitialisationContext& context, std::vector<double>& y, std::vector<double>& yp) {
  const WheelsetEquations& equations = context.equations;
  const ContactFormulation formulation = context.formulation;
  const FollowedBranches& branches = context.branches;
  const int n = unknown_count(formulation, branches.any_two_point());
  yp.assign(static_cast<size_t>(n), 0.0);
  std::vector<double> r(static_cast<size_t>(n));
  if (formulation == ContactFormulation::kElastic) {
    equations.residual(formulation, y.data(), yp.data(), context.contact_at(y.data()), branches, r.data());
    for (int k = 0; k <= kUnknownSpinRate; ++k) yp[k] = -r[k] / equations.derivative_coefficient(k);
    return;
  }
  // Rigid: mu = 0, q' = v; v' and N from the equations of motion and the constraints on the
  // acceleration level, G v' + (dG/dt) v = 0, with dG/dt v by a difference along v. The creep
  // forces depend on N (Hertz), so iterate. Every constraint: both wheels' points, and the second
  // point of a wheel in two-point contact.
  const std::vector<ActiveConstraint> active = active_constraints(branches);
  y[kUnknownMuLeft] = y[kUnknownMuRight] = 0.0;
  if (branches.any_two_point()) y[kUnknownSecondMuLeft] = y[kUnknownSecondMuRight] = 0.0;
  const double eps = kGradientRateStep;
  std::vector<double> ahead = y;
  for (int k = 0; k < kPoseUnknowns; ++k) ahead[k] += eps * y[kPoseUnknowns + k];
  // Ahead along the motion: the pose moved by eps v and, where the rails move under the wheelset,
  // the rails eps later (the constraints' explicit change with time, d(G)/dt v and d(gap_rate)/dt:
  // V^2 times the irregularity's curvature, up to tenths of g).
  const ContactResult c_ahead =
      context.contact_later ? context.contact_later(ahead.data(), eps) : context.contact_at(ahead.data());
  const Eigen::Vector4d m = equations.mass_diagonal();
  const int count = static_cast<int>(active.size());
  for (int iteration = 0; iteration < kMaxNormalForceIterations; ++iteration) {
    const ContactResult c = context.contact_at(y.data());
    std::fill(yp.begin(), yp.end(), 0.0);
    equations.residual(formulation, y.data(), yp.data(), c, branches, r.data());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4 + count, 4 + count);
    Eigen::VectorXd b(4 + count);
    for (int k = 0; k < 4; ++k) {
      a(k, k) = m[k];
      b[k] = -r[kPoseUnknowns + k];
    }
    const double scale = equations.force_scale();
    for (int i = 0; i < count; ++i) {
      const WheelConstraint& w = active[static_cast<size_t>(i)].of(c);
      const WheelConstraint& w_ahead = active[static_cast<size_t>(i)].of(c_ahead);
      // The gap rates' change along the motion too (the rails moving under the wheelset).
      double g_dot_v = (w_ahead.gap_rate - w.gap_rate) / eps;
      for (int k = 0; k < 4; ++k) {
        // r holds the forces of the current N; the unknown is the change of N (scaled).
        a(k, 4 + i) = -scale * w.normal_z * w.gap_gradient[k];
        a(4 + i, k) = w.gap_gradient[k];
        g_dot_v += (w_ahead.gap_gradient[k] - w.gap_gradient[k]) / eps * y[kPoseUnknowns + k];
      }
      b[4 + i] = -g_dot_v;
    }
    const Eigen::VectorXd x = a.fullPivLu().solve(b);
    double change = 0.0;
    for (int i = 0; i < count; ++i) {
      change = std::max(change, std::abs(x[4 + i]));
      y[static_cast<size_t>(active[static_cast<size_t>(i)].normal)] += x[4 + i];
    }
    for (int k = 0; k < 4; ++k) yp[kPoseUnknowns + k] = x[k];
    if (change < kNormalForceTolerance) break;
  }
  // The spin and the pose rows with the final N.
  std::vector<double> zero(static_cast<size_t>(n), 0.0);
  equations.residual(formulation, y.data(), zero.data(), context.contact_at(y.data()), branches, r.data());
  yp[kUnknownSpinRate] = -r[kUnknownSpinRate] / equations.parameters().spin_inertia;
  for (int k = 0; k < kPoseUnknowns; ++k) yp[k] = y[kPoseUnknowns + k];
}

}  // namespace wrc
