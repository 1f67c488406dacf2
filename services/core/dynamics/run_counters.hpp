#pragma once
/// @file
/// The counters of one run, summed across every integrator restart (IDAReInit resets IDA's own).

namespace wrc {

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
  long contact_switches = 0;   ///< contact-point switches located as events (both wheels) [-]
  long contact_queries = 0;    ///< contact evaluations asked for (a batch counts once) [-]
  long contact_configurations = 0;  ///< configurations in them [-]
  long contact_retries = 0;    ///< contact queries re-sent after a timeout (over the bus) [-]
  long contact_timeouts = 0;   ///< attempt rounds without a reply (the run waited for a service) [-]
  int last_order = 0;          ///< method order of the last step [-]
  double last_step = 0;        ///< size of the last step [s]

  RunCounters& operator+=(const RunCounters& o) {
    steps += o.steps;
    residual_evals += o.residual_evals;
    jacobian_evals += o.jacobian_evals;
    jacobian_residual_evals += o.jacobian_residual_evals;
    lin_setups += o.lin_setups;
    err_test_fails += o.err_test_fails;
    nonlin_iters += o.nonlin_iters;
    nonlin_conv_fails += o.nonlin_conv_fails;
    root_evals += o.root_evals;
    root_returns += o.root_returns;
    restarts += o.restarts;
    contact_switches += o.contact_switches;
    contact_queries += o.contact_queries;
    contact_configurations += o.contact_configurations;
    contact_retries += o.contact_retries;
    contact_timeouts += o.contact_timeouts;
    return *this;
  }
};

}  // namespace wrc
