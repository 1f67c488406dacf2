// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The counters of one run, summed across every integrator restart (IDAReInit resets IDA's own);
/// their names, units and meanings are run_counter_table()'s (core/dynamics/run_counter_table.hpp).

namespace wrc {

class ContactEvaluator;

struct RunCounters {
  long steps = 0;              ///< accepted integrator steps [-]
  long residual_evals = 0;     ///< residual evaluations by IDA (not those of the Jacobian) [-]
  long jacobian_evals = 0;     ///< Jacobian evaluations (each one batch of perturbed states) [-]
  long jacobian_residual_evals = 0;  ///< residual evaluations for the finite-difference Jacobians [-]
  long lin_setups = 0;         ///< linear solver set-ups [-]
  long err_test_fails = 0;     ///< local error test failures [-]
  long nonlin_iters = 0;       ///< Newton iterations [-]
  long nonlin_conv_fails = 0;  ///< Newton convergence failures [-]
  long root_evals = 0;         ///< evaluations of the event functions [-]
  long root_returns = 0;       ///< returns at an event (contact-point switch, flange contact) [-]
  long restarts = 0;           ///< re-initialisations after an event or a model swap [-]
  long convergence_restarts = 0;  ///< of those, after the corrector failed at every step size (rigid) [-]
  long contact_switches = 0;   ///< contact-point switches located as events (both wheels) [-]
  long missed_switches = 0;    ///< of those, found by the branch check at an accepted step, not by root finding [-]
  long two_point_entries = 0;  ///< switches into rigid two-point contact (sliding on a switching surface) [-]
  double two_point_time = 0;   ///< simulated time with a wheel in two-point contact, summed over the wheels [s]
  double max_branch_excess = 0;  ///< largest height of a followed point above the lowest minimum at an accepted step [m]
  long floored_patches = 0;    ///< patches at accepted steps whose lateral curvature was floored (conformal, Hertz does not hold) [-]
  double floored_time = 0;     ///< simulated time of the steps ending with such a patch [s]
  long contact_queries = 0;    ///< contact evaluations asked for (a batch counts once) [-]
  long contact_configurations = 0;  ///< configurations in them [-]
  long contact_sent_ahead = 0;  ///< of those, sent before they were asked for: the next step's first state and Newton matrix with the accepted step's, a Newton matrix with its residual [-]
  long contact_ahead_used = 0;  ///< of those, asked for later (answered from the cache) [-]
  long contact_retries = 0;    ///< contact queries re-sent after a timeout (over the bus) [-]
  long contact_timeouts = 0;   ///< attempt rounds without a reply (the run waited for a service) [-]
  long contact_failovers = 0;  ///< queries sent to every other READY instance after a round without a reply [-]
  // where the answered queries' time over the bus went, summed (QueryTimes, contact_evaluator.hpp)
  double bus_round_trip_time = 0;      ///< first send to the reply handled [s]
  double bus_send_time = 0;            ///< the dynamics' stamping, encoding, signing and send call [s]
  double bus_transfer_time = 0;        ///< to the query's receipt by the service's LCM [s]
  double bus_service_wakeup_time = 0;  ///< receipt to the service's handler (wake-up, verification, decoding) [s]
  double bus_compute_time = 0;         ///< the service's evaluation [s]
  double bus_reply_time = 0;           ///< end of the evaluation to the reply's receipt by the dynamics' LCM [s]
  double bus_client_wakeup_time = 0;   ///< receipt to the reply handled (wake-up, verification, decoding) [s]
  int last_order = 0;          ///< method order of the last step [-]
  double last_step = 0;        ///< size of the last step [s]

  /// Adds the counters of a later stretch of the run: sums, the larger of max_branch_excess;
  /// last_order and last_step stay (run_counter_table() says which is which).
  RunCounters& operator+=(const RunCounters& later);
  /// Adds an evaluator's counts of retries, timeouts, fail-overs and its query times.
  void add_evaluator(const ContactEvaluator& evaluator);
};

}  // namespace wrc
