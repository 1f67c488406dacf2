// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/segment_settings.hpp"
#include "core/dynamics/wheelset_equations.hpp"
#include "core/numerics/number_text.hpp"

namespace wrc {
namespace {

// [-] the weighted RMS Newton step below which the iteration has converged: every unknown within
// a thousandth of its tolerance.
constexpr double kConvergedStep = 1e-3;
// [-] the smallest damping factor of a Newton step.
constexpr double kSmallestDamping = 1.0 / 64.0;
// [-] the first and largest step of the share of the irregularities and the holds' offsets in the
// rest state's continuation, and the smallest before it gives up.
constexpr double kFirstShareStep = 0.25;
constexpr double kSmallestShareStep = 1.0 / 256.0;

double weighted_rms(const Eigen::VectorXd& v, const std::vector<double>& w) {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i) sum += std::pow(v[i] * w[static_cast<size_t>(i)], 2);
  return std::sqrt(sum / static_cast<double>(std::max<Eigen::Index>(v.size(), 1)));
}

// "body 'NAME' unknown k" of state index i.
std::string unknown_name(const VehicleDae& dae, const VehicleLayout& layout, Eigen::Index i) {
  const VehicleDescription& v = dae.equations().vehicle();
  for (size_t b = 0; b < v.bodies.size(); ++b)
    if (i >= layout.offset[b] && i < layout.offset[b] + layout.size[b])
      return "body '" + v.bodies[b].name + "' unknown " + std::to_string(i - layout.offset[b]);
  return "unknown " + std::to_string(i);
}

}  // namespace

std::vector<double> equilibrium_weights(const VehicleDae& dae, double position_tolerance, double velocity_tolerance) {
  const VehicleEquations& e = dae.equations();
  const VehicleLayout layout = dae.layout();
  std::vector<double> w;
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    for (int k = 0; k < layout.size[b]; ++k) {
      const bool wheelset = e.wheelset_of_body(b) >= 0;
      const double tol = wheelset ? (k < kPoseUnknowns ? position_tolerance
                                     : k <= kUnknownSpinRate ? velocity_tolerance
                                                             : kScaledForceTolerance)
                                  : (k < static_cast<int>(kBodyCoordinates) ? position_tolerance : velocity_tolerance);
      w.push_back(1.0 / tol);
    }
  }
  return w;
}

VehicleEquilibrium vehicle_equilibrium(VehicleDae& dae, double t, std::vector<double> y,
                                       const std::vector<double>& weights, const std::vector<HeldWheelset>& held,
                                       int max_iterations) {
  const VehicleLayout layout = dae.layout();
  const Eigen::Index n = layout.unknowns;
  if (static_cast<Eigen::Index>(y.size()) != n || static_cast<Eigen::Index>(weights.size()) != n)
    throw std::logic_error("vehicle_equilibrium: a guess or weights of another layout");
  const std::vector<double> zero(static_cast<size_t>(n), 0.0);
  Eigen::VectorXd r(n), r_trial(n);
  Eigen::MatrixXd jac(n, n);
  // The rows and columns of the held wheelsets: its lateral and yaw balance rows hold y and yaw.
  struct Hold {
    Eigen::Index row, column;
    double value;
  };
  std::vector<Hold> holds;
  for (const HeldWheelset& h : held) {
    if (h.wheelset >= dae.equations().wheelset_count())
      throw std::invalid_argument("vehicle_equilibrium: wheelset " + std::to_string(h.wheelset) + " of " +
                                  std::to_string(dae.equations().wheelset_count()));
    const Eigen::Index off = layout.offset[dae.equations().wheelset_body(h.wheelset)];
    holds.push_back({off + kUnknownYDot, off + kUnknownY, h.lateral});
    holds.push_back({off + kUnknownYawDot, off + kUnknownYaw, h.yaw});
  }
  const auto residual = [&](const std::vector<double>& state, Eigen::VectorXd& out) {
    dae.residual(t, state.data(), zero.data(), out.data());
    for (const Hold& h : holds) out[h.row] = state[static_cast<size_t>(h.column)] - h.value;
  };
  residual(y, r);
  VehicleEquilibrium result;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    jac.setZero();
    dae.jacobian(t, 0.0, y.data(), zero.data(), r.data(), DenseMatrixView{jac.data(), n});
    for (const Hold& h : holds) {
      jac.row(h.row).setZero();
      jac(h.row, h.column) = 1.0;
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(jac);
    if (!lu.isInvertible()) {
      std::ostringstream msg;
      msg << "the vehicle's equilibrium at t = " << t << " s: the Newton matrix is singular (rank " << lu.rank()
          << " of " << n << "): a body is not held in some direction";
      throw std::runtime_error(msg.str());
    }
    const Eigen::VectorXd step = -lu.solve(r);
    const double norm = weighted_rms(step, weights);
    result.iterations = iteration;
    result.last_step = norm;
    if (norm < kConvergedStep) {
      for (Eigen::Index i = 0; i < n; ++i) y[static_cast<size_t>(i)] += step[i];
      result.state = std::move(y);
      return result;
    }
    // Damped: the next Newton step (with this matrix) must be shorter than this one.
    double lambda = 1.0;
    std::vector<double> trial(y.size());
    for (;;) {
      for (Eigen::Index i = 0; i < n; ++i) trial[static_cast<size_t>(i)] = y[static_cast<size_t>(i)] + lambda * step[i];
      residual(trial, r_trial);
      const double next = weighted_rms(lu.solve(r_trial), weights);
      if (std::isfinite(next) && (next < (1.0 - lambda / 4.0) * norm || lambda <= kSmallestDamping)) break;
      lambda *= 0.5;
    }
    y = trial;
    r = r_trial;
  }
  Eigen::Index worst = 0;
  r.cwiseAbs().maxCoeff(&worst);
  std::ostringstream msg;
  msg << "the vehicle's equilibrium at t = " << t << " s does not converge in " << max_iterations
      << " Newton iterations (last step " << result.last_step << " times the tolerance; largest residual "
      << r[worst] << " at " << unknown_name(dae, layout, worst) << ")";
  throw std::runtime_error(msg.str());
}

namespace {

// The rest state on the rails as the equations place them now.
std::vector<double> rest_state_on_rails(VehicleDae& dae, ContactFormulation own, double t, double position_tolerance,
                                        double velocity_tolerance, const std::vector<HeldWheelset>& held) {
  VehicleEquations& e = dae.equations();
  VehicleContact& contact = dae.contact();
  for (size_t w = 0; w < contact.size(); ++w) contact.wheelset(w).set_formulation(ContactFormulation::kRigid);
  const VehicleLayout rigid = dae.layout();
  std::vector<double> y(static_cast<size_t>(rigid.unknowns), 0.0);
  for (size_t w = 0; w < e.wheelset_count(); ++w) {
    double* u = y.data() + rigid.offset[e.wheelset_body(w)];
    const double r0 = e.wheelset(w).nominal_radius();
    u[kUnknownZ] = r0;
    u[kUnknownSpinRate] = e.speed() / r0;
    u[kUnknownNormalLeft] = u[kUnknownNormalRight] = 1.0;  // the static wheel load each
  }
  y = vehicle_equilibrium(dae, t, std::move(y), equilibrium_weights(dae, position_tolerance, velocity_tolerance), held)
          .state;
  if (own == ContactFormulation::kRigid) return y;
  std::vector<double> elastic;
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    const auto first = y.begin() + rigid.offset[b];
    const bool wheelset = e.wheelset_of_body(b) >= 0;
    elastic.insert(elastic.end(), first, first + (wheelset ? kElasticUnknowns : rigid.size[b]));
    if (wheelset) elastic[elastic.size() - kElasticUnknowns + kUnknownZ] -= kElasticStartDepth;
  }
  for (size_t w = 0; w < contact.size(); ++w) contact.wheelset(w).set_formulation(ContactFormulation::kElastic);
  return vehicle_equilibrium(dae, t, std::move(elastic),
                             equilibrium_weights(dae, position_tolerance, velocity_tolerance), held)
      .state;
}

}  // namespace

std::vector<double> vehicle_rest_state(VehicleDae& dae, ContactFormulation own, double t, double position_tolerance,
                                       double velocity_tolerance, const std::vector<HeldWheelset>& held,
                                       bool continued) {
  VehicleEquations& e = dae.equations();
  try {
    return rest_state_on_rails(dae, own, t, position_tolerance, velocity_tolerance, held);
  } catch (const std::runtime_error& direct) {
    const bool off_centre = std::any_of(held.begin(), held.end(),
                                        [](const HeldWheelset& h) { return h.lateral != 0.0 || h.yaw != 0.0; });
    if (!continued || (!e.has_irregularities() && !off_centre)) throw;
    // Continued from the nominal rails with the held wheelsets centred: the share of the
    // irregularities and of the holds' offsets raised from 0 to 1 in the formulation own (an
    // elastic contact is smooth where a rigid one's contact point jumps), each equilibrium the next
    // one's guess, the share's step halved where Newton does not converge.
    auto holds_at = [&held](double share) {
      std::vector<HeldWheelset> scaled = held;
      for (HeldWheelset& h : scaled) {
        h.lateral *= share;
        h.yaw *= share;
      }
      return scaled;
    };
    std::string reached = "0";
    try {
      e.set_irregularity_share(0.0);
      std::vector<double> y = rest_state_on_rails(dae, own, t, position_tolerance, velocity_tolerance, holds_at(0.0));
      double share = 0.0;
      double step = kFirstShareStep;
      while (share < 1.0) {
        const double next = std::min(1.0, share + step);
        e.set_irregularity_share(next);
        try {
          y = vehicle_equilibrium(dae, t, y, equilibrium_weights(dae, position_tolerance, velocity_tolerance),
                                  holds_at(next))
                  .state;
          share = next;
          reached = number_text(share);
          step = std::min(2.0 * step, kFirstShareStep);
        } catch (const std::runtime_error&) {
          step *= 0.5;
          if (step < kSmallestShareStep) throw;
        }
      }
      e.set_irregularity_share(1.0);
      return y;
    } catch (const std::exception& stopped) {
      e.set_irregularity_share(1.0);
      throw std::runtime_error(std::string(direct.what()) + "; continued from the nominal rails" +
                               (off_centre ? " with the held wheelsets centred" : "") + ", the equilibrium reached " +
                               reached + " of the way: " + stopped.what());
    }
  }
}

}  // namespace wrc
