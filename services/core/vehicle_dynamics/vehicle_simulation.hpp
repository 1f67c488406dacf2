// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A vehicle run: the equations of vehicle_equations.hpp integrated by SUNDIALS IDA step by step
/// from the vehicle's equilibrium on the track at t = 0 (vehicle_equilibrium.hpp), every
/// wheelset's contact from one contact evaluator in one batch per evaluation
/// (vehicle_contact.hpp), output samples every output period.
///
/// Rigid contact follows each wheel's point as the lone wheelset's run does (docs/vehicle.md,
/// "Contact-point switches per wheelset"): every wheelset's event functions, its switches and
/// two-point sliding (core/dynamics/contact_switching.hpp) at its events, and the vehicle restarted
/// from consistent values (vehicle_restart.hpp).
///
/// Model swaps change every wheelset's model at a step boundary. What the lone wheelset's run has
/// and this one does not have yet (docs/vehicle.md): the states sent ahead with the accepted step.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/contact_switching.hpp"
#include "core/dynamics/swap_queue.hpp"
#include "core/dynamics/ida_integrator.hpp"
#include "core/dynamics/output_sampler.hpp"
#include "core/dynamics/run_extremes.hpp"
#include "core/dynamics/wheel_output.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_parameters.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/vehicle/vehicle_description.hpp"
#include "core/vehicle_dynamics/vehicle_contact.hpp"
#include "core/vehicle_dynamics/vehicle_dae.hpp"
#include "core/vehicle_dynamics/vehicle_equations.hpp"
#include "core/vehicle_dynamics/vehicle_equilibrium.hpp"

namespace wrc {

/// A vehicle's state to start a run from instead of its rest: the end of a run at another speed
/// (a continuation, core/dynamics/hunting_continuation.hpp).
struct VehicleStart {
  /// Each body's displacement and rates in its track frame, as VehicleSnapshot::bodies has them
  std::vector<BodyState> bodies;
  std::vector<double> spin_rate_offsets;  ///< each wheelset's spin rate minus V / r0 [rad/s]
};

/// A whole vehicle run.
struct VehicleRunSpec {
  VehicleDescription vehicle;
  /// The run: speed, material, FASTSIM grid, gravity and flange angle from run.wheelset (its
  /// masses, loads and suspension are the vehicle's instead), the integrator settings, the track
  /// and its irregularities. The run starts from the vehicle's equilibrium at rest; run.initial's
  /// y and yaw hold its first wheelset at that lateral shift and yaw there (the rest of the vehicle
  /// in equilibrium about it), released at t = 0; its rates must be 0.
  RunSpec run;
  /// Where the run starts instead (run.initial then all 0): on straight track, each wheelset
  /// projected onto its contact constraints (rigid), the derivatives consistent with the state.
  std::optional<VehicleStart> start;
};

/// The vehicle at one time.
struct VehicleSnapshot {
  double t = 0;                  ///< simulated time [s]
  /// Each body's displacement from its nominal position in its own track frame and its rates, in
  /// the order of the vehicle's bodies (a wheelset's z from its position's z; pitch 0)
  std::vector<BodyState> bodies;
  std::vector<double> spin_rates;  ///< each wheelset's spin [rad/s], in the order of the wheelsets
  /// Each wheelset's wheels, left [0] and right [1] (docs/run-quantities.md), in the order of the
  /// wheelsets: at an output time between two steps, the contact interpolated as the lone
  /// wheelset's run does
  std::vector<std::array<WheelOutput, 2>> wheels;
  /// Each car body's and frame's absolute acceleration [m/s^2] along y and z of its track frame,
  /// gravity not included; zeros for the wheelsets; in the order of the bodies
  std::vector<std::array<double, 2>> accelerations;
};

/// The largest absolute accelerations of a car body or a frame over a run, along y and z of its
/// track frame, gravity not included [m/s^2], over the output samples, with the time and the
/// body's distance along the track where they occurred (what ride comfort and the running
/// behaviour are judged from).
struct BodyAccelerationMaxima {
  RunMaximum lateral;
  RunMaximum vertical;
};

class VehicleSimulation : public Simulation, private DaeSystem {
 public:
  /// @param nominal_radius r0 of the wheel profile [m]
  /// @throws std::invalid_argument for an invalid spec (naming the body and key), a null contact.
  VehicleSimulation(VehicleRunSpec spec, std::shared_ptr<ContactEvaluator> contact, double nominal_radius);
  ~VehicleSimulation() override;
  VehicleSimulation(const VehicleSimulation&) = delete;
  VehicleSimulation& operator=(const VehicleSimulation&) = delete;

  /// Called with every output sample (t = 0, every output period, t_end).
  void on_output(std::function<void(const VehicleSnapshot&)> callback) { on_output_ = std::move(callback); }

  /// The equilibrium at t = 0 (rigid contact first, then the model's own formulation) and the
  /// first output. A rigid model with no equilibrium on irregular rails or with its first wheelset
  /// held off centre (a wheel at rest where its contact point jumps) starts from the equilibrium
  /// on the nominal rails (with the hold, or else centred and the first wheelset then moved to its
  /// held y and yaw) with each wheelset placed onto its rails and consistent derivatives, and says
  /// so in start_note().
  /// @throws std::runtime_error when there is no start (the message says why).
  void start() override;
  /// How the run started when not from its equilibrium on its rails; empty otherwise.
  const std::string& start_note() const { return start_note_; }
  /// One integrator step with the outputs it passes; false once the run is over (state()).
  bool advance() override;
  /// start() if not started, then advance() to the end.
  void run();
  /// Ends the run at the next step boundary with RunState::kStopped.
  void request_stop() override { stop_requested_ = true; }
  /// A live swap of every wheelset's model at the next step boundary.
  void request_swap(std::shared_ptr<ContactEvaluator> next) override { swap_queue_.request(std::move(next)); }
  /// A swap at the first step boundary at or after time t [s].
  void schedule_swap(double t, std::shared_ptr<ContactEvaluator> next) override {
    swap_queue_.schedule(t, std::move(next));
  }
  const std::vector<SwapRecord>& swaps() const override { return swaps_; }
  /// Wheelset w at the output sample s in the lone wheelset's terms (z: the centre's height above
  /// the rails), with the contact model in use.
  WheelsetSnapshot wheelset_snapshot(const VehicleSnapshot& s, size_t w) const;
  /// Wheelset w's parameters as the lone wheelset's run states them: its mass and inertias, the
  /// run's material, speed and flange angle, and its static axle load as its total vertical load
  /// (vertical_force less its weight), what Prud'homme's limit takes.
  WheelsetParameters wheelset_parameters(size_t w) const;

  RunState state() const override { return state_; }
  const std::string& message() const override { return message_; }
  double time() const override { return t_; }
  std::string model() const override { return contact_.evaluator()->model(); }
  /// The vehicle now (after the last step).
  VehicleSnapshot snapshot();
  /// The vehicle now as a start of another run (VehicleRunSpec::start).
  VehicleStart continuation();
  /// The vehicle at rest in its track frames where time t places it: F(t, y, 0) = 0 solved from the
  /// state now (vehicle_equilibrium.hpp). In a curve of constant radius and cant, the steady
  /// curving state a run settles on; the run itself is not changed.
  /// @throws std::runtime_error when the iteration finds none.
  VehicleSnapshot steady_state(double t);
  /// The state vector now and its layout (vehicle_equations.hpp).
  std::vector<double> state_vector() const;
  VehicleLayout layout() const { return dae_.layout(); }
  /// Every contact-point switch so far, of every wheelset (SwitchRecord::wheelset names it).
  const std::vector<SwitchRecord>& switches() const { return switch_log_; }
  /// Counters summed over the run: IDA's over every segment, the Jacobians, the contact batches,
  /// the switches and restarts.
  RunCounters counters() const override;
  const VehicleEquations& equations() const { return equations_; }
  /// The largest |Y/Q|, |sum Y|, T gamma and p_max of wheelset w so far, over every accepted step
  /// and output sample (its distance: V t), as the lone wheelset's run takes them.
  const RunExtremes& extremes(size_t w) const { return samplers_[w].extremes(); }
  /// Body b's largest accelerations so far (b in the order of the vehicle's bodies; a wheelset's
  /// stay 0).
  const BodyAccelerationMaxima& acceleration_maxima(size_t b) const { return acceleration_maxima_[b]; }
  /// Wheelset w's wheels at the last accepted step.
  const std::array<WheelOutput, 2>& last_step_wheels(size_t w) const { return samplers_[w].last_step().wheels; }
  /// The formulation of the model's contact (every wheelset's).
  ContactFormulation formulation() const { return formulation_of(*contact_.evaluator()); }
  /// Each wheelset's static wheel load, the scale of its normal forces [N].
  const std::vector<double>& wheel_loads() const { return wheel_loads_; }

 private:
  int residual(double t, const double* y, const double* yp, double* r) override;
  int jacobian(double t, double cj, const double* y, const double* yp, const double* r, DenseMatrixView jac) override;
  int roots(double t, const double* y, double* g) override;
  void message(const char* function, const char* text) override;
  VehicleSnapshot snapshot_of(double t, const std::vector<double>& y);
  /// Each wheelset's contact at the accepted state into its sampler (restart: a segment starts).
  void record_step_contact(bool restart);
  void emit_outputs_until(double t);
  void fail(const std::string& why);
  /// Wheelset w's consistent initialisation and switching, on its block of the state.
  InitialisationContext initialisation(size_t w);
  SwitchingContext switching(size_t w);
  /// The switches of the events the last step found, then a restart.
  void handle_roots();
  /// After the corrector failed at every step size: every wheel in two-point contact keeps its
  /// more loaded point, then a restart.
  void restart_after_convergence_failure();
  /// Follows every wheelset's points at the accepted step, or restarts where a followed point is
  /// not the lowest (a switch the root finding did not see).
  void check_branches();
  /// A new segment from the blocks (per body): every wheelset settled on its lowest branches,
  /// derivatives consistent, the step's contact recorded anew.
  void restart(std::vector<std::vector<double>> blocks);
  /// Every wheelset's model swapped to next: each wheelset's block made one of next's formulation
  /// (as the lone wheelset's swap makes it), the vehicle restarted there. A swap that fails keeps
  /// the model and says why in message() without ending the run.
  void perform_swap(std::shared_ptr<ContactEvaluator> next);
  /// The state of spec_.start (every wheelset in its own formulation, projected when rigid).
  std::vector<double> continued_state();
  /// Rigid: the rest state on the nominal rails (the held wheelsets held; where that has none, the
  /// vehicle's centred rest with the held wheelsets moved to their y and yaw), each wheelset then
  /// settled on its lowest branches of the (irregular) rails at t = 0. Says which in how.
  std::vector<double> placed_on_rails(const std::vector<HeldWheelset>& held, std::string& how);

  VehicleRunSpec spec_;
  std::vector<double> wheel_loads_;
  VehicleEquations equations_;
  VehicleContact contact_;
  VehicleDae dae_;
  IdaIntegrator integrator_;
  std::function<void(const VehicleSnapshot&)> on_output_;
  std::vector<OutputSampler> samplers_;  // one per wheelset
  std::vector<BodyAccelerationMaxima> acceleration_maxima_;  // one per body
  bool started_ = false;
  double t_ = 0;
  RunState state_ = RunState::kRunning;
  std::string message_;
  std::string start_note_;
  std::string last_error_;           // what the equations last threw (the contact model's reason)
  std::string last_solver_message_;  // IDA's last message
  bool stop_requested_ = false;
  std::vector<SwapRecord> swaps_;
  SwapQueue swap_queue_;
  RunCounters accumulated_;  // IDA's counters of the segments before the current one
  RunCounters own_;          // the switches and restarts
  std::vector<SwitchRecord> switch_log_;
  int convergence_restarts_in_a_row_ = 0;
};

/// Each wheelset's static wheel load on level track [N]: the vehicle's weight and vertical
/// external forces shared evenly by its wheels.
/// @param gravity g [m/s^2]
std::vector<double> static_wheel_loads(const VehicleDescription& vehicle, double gravity);

}  // namespace wrc
