// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A wheelset run: the equations of wheelset_equations.hpp integrated by SUNDIALS IDA step by
/// step, with the contact from a ContactEvaluator, events where the contact point jumps, restarts
/// with consistent initial values, and model swaps at step boundaries.

#include <array>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/consistent_initialisation.hpp"
#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/run_extremes.hpp"
#include "core/dynamics/sundials_support.hpp"
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

/// A model swap that took effect.
struct SwapRecord {
  double t = 0;        ///< simulated time of the step boundary where it took effect [s]
  std::string from;    ///< model before
  std::string to;      ///< model after
};

/// One located switch of a wheel's contact point (or regime).
struct SwitchRecord {
  double t = 0;        ///< [s]
  int wheel = 0;       ///< 0 left, 1 right
  double s_from = 0;   ///< wheel coordinate before [m]
  double s_to = 0;     ///< after [m]
};

/// How a run ends.
enum class RunState { kRunning, kFinished, kFailed, kStopped };

class WheelsetSimulation {
 public:
  /// @param nominal_radius r0 of the wheel profile (nominal spin V / r0) [m].
  /// @throws std::invalid_argument for an invalid spec or a null contact.
  WheelsetSimulation(RunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius);
  ~WheelsetSimulation();
  WheelsetSimulation(const WheelsetSimulation&) = delete;
  WheelsetSimulation& operator=(const WheelsetSimulation&) = delete;

  /// Called with every output sample (t = 0, every output period, t_end).
  void on_output(std::function<void(const WheelsetSnapshot&)> callback) { on_output_ = std::move(callback); }

  /// Consistent initial values at t = 0 and the first output. Throws std::runtime_error when no
  /// consistent state exists (the message says why).
  void start();
  /// One integrator step, with the outputs, events and restarts it passes. A pending swap takes
  /// effect first. Returns false once the run is over (state() says how).
  bool advance();
  /// Runs advance() until the end.
  void run();

  /// Takes effect at the next step boundary (the next advance()).
  void request_swap(std::shared_ptr<ContactEvaluator> next);
  /// A swap to next at the first step boundary at or after time t [s]: reproduces, bit for bit, a
  /// live swap recorded at t (which took effect at a step boundary).
  void schedule_swap(double t, std::shared_ptr<ContactEvaluator> next);
  /// Ends the run at the next step boundary with RunState::kStopped.
  void request_stop() { stop_requested_ = true; }

  RunState state() const { return state_; }
  const std::string& message() const { return message_; }
  double time() const { return t_; }
  std::string model() const { return contact_->model(); }
  ContactFormulation formulation() const { return formulation_; }
  /// The wheelset now (after the last step).
  WheelsetSnapshot snapshot();
  /// Counters summed over the whole run.
  RunCounters counters() const;
  const std::vector<SwapRecord>& swaps() const { return swaps_; }
  const std::vector<SwitchRecord>& switches() const { return switch_log_; }
  /// The largest |Y/Q|, |sum Y|, T gamma and p_max so far, over every accepted step and output
  /// sample, with their time and distance travelled (docs/run-quantities.md).
  const RunExtremes& extremes() const { return extremes_; }
  const RunSpec& spec() const { return spec_; }
  const WheelsetEquations& equations() const { return equations_; }

  /// IDA's residual, Jacobian and event callbacks (public for the C trampolines only).
  /// Places the equations on the track where the wheelset is at time t [s] (s = speed t).
  void place_on_track(double t);
  int residual_callback(const double* y, const double* yp, double* r);
  int jacobian_callback(double cj, const double* y, const double* yp, const double* r, SUNMatrix jac);
  int root_callback(const double* y, double* g);
  /// IDA's error and warning text [-]: kept for the run's failure message instead of printed (a
  /// failure the run recovers from, a convergence restart, is no error for the user).
  void solver_message(const char* function, const char* text);

 private:
  struct CachedContact {
    std::vector<double> key;
    ContactResult result;
  };
  const ContactResult& contact_at(const double* y);
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch);
  /// Unknowns of the current formulation and branches (unknown_count()).
  int unknowns() const;
  /// Follows other branches: the state resized to their layout, the contact cache cleared.
  void set_branches(const FollowedBranches& branches, std::vector<double>& y);
  /// Wheel i leaves its branch for the point at target_s [m] (an event, or a switch the branch
  /// check found at a step): one-point contact on the target, or, where one-point contact would
  /// at once switch back (the point it leaves is not separating and two-point contact loads both
  /// points), rigid two-point contact on both: Filippov's sliding mode on the switching surface
  /// (only with IntegratorSettings::two_point_sliding; without it, one-point contact on the target).
  /// Sets branches_ and the state y (positions and velocities projected).
  void switch_wheel(int wheel, double target_s, std::vector<double>& y);
  /// Releases the point of wheel i whose normal force fell to 0 (second: the second point).
  void release_point(int wheel, bool second, std::vector<double>& y);
  /// How far a followed point is above the lowest minimum (or past a fold) at the contact of y,
  /// per wheel [m] (<= 0 on the right branch): -switch_function.
  std::array<double, 2> branch_excess(const ContactResult& c) const;

  /// The run's equations, formulation, branches and contact for the consistent initialisation
  /// (consistent_initialisation.hpp).
  InitialisationContext initialisation();
  void begin_segment(std::vector<double> y, bool first);
  void perform_swap(std::shared_ptr<ContactEvaluator> next);
  void handle_roots();
  /// Projects y onto the constraints, switches every wheel whose followed point is not the lowest
  /// (at most kMaxSwitchesPerEvent times; not without IntegratorSettings::two_point_sliding) and
  /// restarts the integrator there.
  void restart_on_right_branches(std::vector<double>& y);
  /// After IDA's corrector failed at every step size (rigid formulation): a wheel in two-point
  /// contact keeps its more loaded point, and the run restarts on the right branches there.
  void restart_after_convergence_failure();
  /// The contact of each wheel at the state y (one contact evaluation, usually cached); forces, when
  /// given, receives each wheel's patch sums.
  std::array<WheelOutput, 2> wheel_outputs(const std::vector<double>& y, std::array<WheelForces, 2>* forces = nullptr);
  /// Every output sample up to t: the state interpolated by IDA, the contact data linearly
  /// between the last two accepted steps (no contact evaluation per sample).
  void emit_outputs_until(double t);
  WheelsetSnapshot snapshot_of(const std::vector<double>& y, double t, const std::array<WheelOutput, 2>& wheels);
  /// The contact data of the step just accepted (and of the previous one).
  struct StepContact {
    double t = 0;
    std::array<WheelOutput, 2> wheels;
    std::array<WheelForces, 2> forces;  // each wheel's patch sums (Y and Q at an output apply its normal force)
  };
  void record_step_contact(bool restart);
  RunCounters ida_counters() const;
  std::vector<double> current_state() const;
  void fail(const std::string& why);

  RunSpec spec_;
  WheelsetEquations equations_;
  std::shared_ptr<ContactEvaluator> contact_;
  ContactFormulation formulation_ = ContactFormulation::kRigid;
  FollowedBranches branches_;
  std::function<void(const WheelsetSnapshot&)> on_output_;

  SundialsContext ctx_;
  std::unique_ptr<SerialVector> y_, yp_, id_, atol_;
  std::unique_ptr<SerialVector> output_state_;  // the state interpolated at an output time
  IdaSolver ida_;
  double t_ = 0;
  double next_output_ = 0;
  long output_index_ = 0;
  RunState state_ = RunState::kRunning;
  std::string message_;
  std::string last_contact_error_;
  std::string last_solver_message_;  // IDA's last error or warning text, for a failure's message
  bool stop_requested_ = false;
  std::shared_ptr<ContactEvaluator> pending_swap_;
  double scheduled_swap_time_ = -1;
  std::shared_ptr<ContactEvaluator> scheduled_swap_;
  RunCounters accumulated_;  // finished segments
  RunCounters own_;          // counted here, not by IDA (queries, Jacobians, restarts, switches)
  std::deque<CachedContact> cache_;
  StepContact previous_step_, current_step_;
  std::vector<SwapRecord> swaps_;
  std::vector<SwitchRecord> switch_log_;
  RunExtremes extremes_;
  int convergence_restarts_in_a_row_ = 0;  // without a step in between
};

}  // namespace wrc
