// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A wheelset run: the equations of wheelset_equations.hpp integrated by SUNDIALS IDA step by
/// step, with the contact from a ContactEvaluator, events where the contact point jumps, restarts
/// with consistent initial values, and model swaps at step boundaries. The run drives its units:
/// the integrator (ida_integrator.hpp), the Jacobian (wheelset_jacobian.hpp), the contact and its
/// cache (wheelset_contact.hpp), the contact-point switches (contact_switching.hpp) and the output
/// samples (output_sampler.hpp).

#include <array>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/swap_queue.hpp"
#include "core/dynamics/contact_switching.hpp"
#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/output_sampler.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/run_extremes.hpp"
#include "core/dynamics/simulation.hpp"
#include "core/dynamics/wheelset_contact.hpp"
#include "core/dynamics/wheelset_equations.hpp"
#include "core/dynamics/wheel_forces.hpp"
#include "core/dynamics/wheel_output.hpp"
#include "core/dynamics/wheelset_parameters.hpp"

namespace wrc {

/// The wheelset at one time, in the conventions of `wrc geometry` (z = height of the centre above
/// the top-of-rail plane).
struct WheelsetSnapshot {
  double t = 0;          ///< simulated time [s]
  double y = 0;          ///< [m]
  double z = 0;          ///< [m]
  double roll = 0;       ///< [rad]
  double yaw = 0;        ///< [rad]
  double y_dot = 0;      ///< [m/s]
  double z_dot = 0;      ///< [m/s]
  double roll_dot = 0;   ///< [rad/s]
  double yaw_dot = 0;    ///< [rad/s]
  double spin_rate = 0;  ///< [rad/s]
  std::array<WheelOutput, 2> wheels;  ///< left [0], right [1]
  std::string model;     ///< contact model in use
};

class WheelsetSimulation : public Simulation, private DaeSystem {
 public:
  /// @param nominal_radius r0 of the wheel profile (nominal spin V / r0) [m].
  /// @throws std::invalid_argument for an invalid spec or a null contact.
  WheelsetSimulation(RunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius);
  ~WheelsetSimulation() override;
  WheelsetSimulation(const WheelsetSimulation&) = delete;
  WheelsetSimulation& operator=(const WheelsetSimulation&) = delete;

  /// Called with every output sample (t = 0, every output period, t_end).
  void on_output(std::function<void(const WheelsetSnapshot&)> callback) { on_output_ = std::move(callback); }

  /// Consistent initial values at t = 0 and the first output. Throws std::runtime_error when no
  /// consistent state exists (the message says why).
  void start() override;
  /// One integrator step, with the outputs, events and restarts it passes. A pending swap takes
  /// effect first. Returns false once the run is over (state() says how).
  bool advance() override;
  /// Runs advance() until the end.
  void run();

  /// Takes effect at the next step boundary (the next advance()).
  void request_swap(std::shared_ptr<ContactEvaluator> next) override;
  /// A swap to next at the first step boundary at or after time t [s]: reproduces, bit for bit, a
  /// live swap recorded at t (which took effect at a step boundary). Every scheduled swap takes
  /// effect, in the order of their times (of equal times, in the order scheduled); several due at
  /// one boundary are performed there one after the other.
  void schedule_swap(double t, std::shared_ptr<ContactEvaluator> next) override;
  /// Ends the run at the next step boundary with RunState::kStopped.
  void request_stop() override { stop_requested_ = true; }

  RunState state() const override { return state_; }
  const std::string& message() const override { return message_; }
  double time() const override { return t_; }
  std::string model() const override { return contact_.evaluator()->model(); }
  ContactFormulation formulation() const { return contact_.formulation(); }
  /// The wheelset now (after the last step).
  WheelsetSnapshot snapshot();
  /// Counters summed over the whole run.
  RunCounters counters() const override;
  const std::vector<SwapRecord>& swaps() const override { return swaps_; }
  const std::vector<SwitchRecord>& switches() const { return switch_log_; }
  /// The largest |Y/Q|, |sum Y|, T gamma and p_max so far, over every accepted step and output
  /// sample, with their time and distance travelled (docs/run-quantities.md).
  const RunExtremes& extremes() const { return output_.extremes(); }
  const RunSpec& spec() const { return spec_; }
  const WheelsetEquations& equations() const { return equations_; }

 private:
  /// The DAE IDA integrates (ida_integrator.hpp): each function first places the equations on the
  /// track where the wheelset is at time t.
  int residual(double t, const double* y, const double* yp, double* r) override;
  int jacobian(double t, double cj, const double* y, const double* yp, const double* r, DenseMatrixView jac) override;
  int roots(double t, const double* y, double* g) override;
  /// The states IDA's next step will ask first (its predictor and, where a new Newton matrix is
  /// due, the Jacobian's perturbations of it), to travel with the query of the accepted state at
  /// time t [s]; empty where IDA has no next step to forecast.
  std::vector<WheelsetContact::Ahead> next_step_ahead(double t);
  /// IDA's error and warning text: kept for the run's failure message instead of printed (a
  /// failure the run recovers from, a convergence restart, is no error for the user).
  void message(const char* function, const char* text) override;

  /// Places the equations on the track where the wheelset is at time t [s] (s = speed t).
  void place_on_track(double t);
  /// The run's equations, formulation, branches and contact for the consistent initialisation
  /// (consistent_initialisation.hpp).
  InitialisationContext initialisation();
  /// The contact-point switches at the current time.
  SwitchingContext switching();
  /// The start's consistent state at t = 0 (both formulations from rigid contact).
  std::vector<double> initial_state();
  void begin_segment(std::vector<double> y, bool first);
  void perform_swap(std::shared_ptr<ContactEvaluator> next);
  /// One IDASolve step's aftermath; false once the run is over.
  bool after_step(const IdaStep& step);
  void handle_roots();
  /// Follows the branches at an accepted step without an event, or restarts where the check finds
  /// a followed point that is not the lowest (rigid formulation).
  void check_branches();
  /// Projects y onto the constraints, switches every wheel whose followed point is not the lowest
  /// and restarts the integrator there.
  void restart_on_right_branches(std::vector<double>& y);
  /// After IDA's corrector failed at every step size (rigid formulation): a wheel in two-point
  /// contact keeps its more loaded point, and the run restarts on the right branches there.
  void restart_after_convergence_failure();
  /// The contact of each wheel at the state y (one contact evaluation, usually cached).
  StepContact step_contact_at(const std::vector<double>& y);
  /// Every output sample up to t [s].
  void emit_outputs_until(double t);
  WheelsetSnapshot snapshot_of(const std::vector<double>& y, double t, const std::array<WheelOutput, 2>& wheels);
  void record_step_contact(bool restart);
  void fail(const std::string& why);

  RunSpec spec_;
  WheelsetEquations equations_;
  WheelsetContact contact_;
  std::function<void(const WheelsetSnapshot&)> on_output_;

  IdaIntegrator integrator_;
  OutputSampler output_;
  double t_ = 0;
  RunState state_ = RunState::kRunning;
  std::string message_;
  std::string last_contact_error_;
  std::string last_solver_message_;  // IDA's last error or warning text, for a failure's message
  bool stop_requested_ = false;
  SwapQueue swap_queue_;
  RunCounters accumulated_;  // finished segments
  RunCounters own_;          // counted here, not by IDA (Jacobians, restarts, switches)
  std::vector<SwapRecord> swaps_;
  std::vector<SwitchRecord> switch_log_;
  int convergence_restarts_in_a_row_ = 0;  // without a step in between
};

}  // namespace wrc
