// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/run_counter_table.hpp"

#include <algorithm>

#include "core/dynamics/contact_evaluator.hpp"

namespace wrc {
namespace {

template <class V>
RunCounter counter(const char* name, const char* unit, const char* description, V RunCounters::*member,
                   CounterSum sum = CounterSum::kSum) {
  RunCounter c;
  static_cast<Parameter<RunCounters>&>(c) = member_parameter<RunCounters>({name, nullptr, unit, description}, member);
  c.sum = sum;
  return c;
}

}  // namespace

const std::vector<RunCounter>& run_counter_table() {
  using C = RunCounters;
  static const std::vector<RunCounter> table{
      counter("steps", "-", "accepted integrator steps", &C::steps),
      counter("residual_evals", "-", "residual evaluations by IDA (not those of the Jacobian)", &C::residual_evals),
      counter("jacobian_evals", "-", "Jacobian evaluations (each one batch of perturbed states)", &C::jacobian_evals),
      counter("jacobian_residual_evals", "-", "residual evaluations for the finite-difference Jacobians",
              &C::jacobian_residual_evals),
      counter("lin_setups", "-", "linear solver set-ups", &C::lin_setups),
      counter("err_test_fails", "-", "local error test failures", &C::err_test_fails),
      counter("nonlin_iters", "-", "Newton iterations", &C::nonlin_iters),
      counter("nonlin_conv_fails", "-", "Newton convergence failures", &C::nonlin_conv_fails),
      counter("root_evals", "-", "evaluations of the event functions", &C::root_evals),
      counter("root_returns", "-", "returns at an event (contact-point switch, flange contact)", &C::root_returns),
      counter("restarts", "-", "re-initialisations after an event or a model swap", &C::restarts),
      counter("convergence_restarts", "-",
              "of those, after the corrector failed at every step size (a wheel in two-point contact keeps its "
              "more loaded point)",
              &C::convergence_restarts),
      counter("contact_switches", "-", "contact-point switches located as events (both wheels)", &C::contact_switches),
      counter("missed_switches", "-", "of those, found by the branch check at an accepted step, not by root finding",
              &C::missed_switches),
      counter("two_point_entries", "-", "switches into rigid two-point contact (sliding on a switching surface)",
              &C::two_point_entries),
      counter("two_point_time", "s", "simulated time with a wheel in two-point contact, summed over the wheels",
              &C::two_point_time),
      counter("max_branch_excess", "m",
              "largest height of a followed point above the lowest minimum at an accepted step", &C::max_branch_excess,
              CounterSum::kMax),
      counter("floored_patches", "-",
              "patches at accepted steps whose lateral curvature was floored (conformal, Hertz does not hold)",
              &C::floored_patches),
      counter("floored_time", "s", "simulated time of the steps ending with such a patch", &C::floored_time),
      counter("contact_queries", "-", "contact evaluations asked for (a batch counts once)", &C::contact_queries),
      counter("contact_configurations", "-", "configurations in them", &C::contact_configurations),
      counter("contact_sent_ahead", "-",
              "of those, sent before they were asked for: the next step's first state and Newton matrix with the "
              "accepted step's, a Newton matrix with its residual",
              &C::contact_sent_ahead),
      counter("contact_ahead_used", "-", "of those, asked for later (answered from the cache)", &C::contact_ahead_used),
      counter("contact_retries", "-", "contact queries re-sent after a timeout (over the bus)", &C::contact_retries),
      counter("contact_timeouts", "-", "attempt rounds without a reply (the run waited for a service)",
              &C::contact_timeouts),
      counter("contact_failovers", "-",
              "queries sent to every other READY instance of the model after a round without a reply",
              &C::contact_failovers),
      counter("bus_round_trip_time", "s", "answered contact queries over the bus: first send to the reply handled, summed",
              &C::bus_round_trip_time),
      counter("bus_send_time", "s", "of that: the dynamics' stamping, encoding, signing and send call",
              &C::bus_send_time),
      counter("bus_transfer_time", "s", "of that: on to the query's receipt by the service's LCM (one host's clock)",
              &C::bus_transfer_time),
      counter("bus_service_wakeup_time", "s",
              "of that: receipt to the service's handler (wake-up, verification, decoding)", &C::bus_service_wakeup_time),
      counter("bus_compute_time", "s", "of that: the service's evaluation", &C::bus_compute_time),
      counter("bus_reply_time", "s",
              "of that: the service's reply (encoding, signing, send call) to its receipt by the dynamics' LCM",
              &C::bus_reply_time),
      counter("bus_client_wakeup_time", "s", "of that: receipt to the reply handled (wake-up, verification, decoding)",
              &C::bus_client_wakeup_time),
      counter("last_order", "-", "method order of the last step", &C::last_order, CounterSum::kKept),
      counter("last_step", "s", "size of the last step", &C::last_step, CounterSum::kKept),
  };
  return table;
}

RunCounters& RunCounters::operator+=(const RunCounters& later) {
  for (const RunCounter& c : run_counter_table()) {
    switch (c.sum) {
      case CounterSum::kSum: c.set(*this, c.get(*this) + c.get(later)); break;
      case CounterSum::kMax: c.set(*this, std::max(c.get(*this), c.get(later))); break;
      case CounterSum::kKept: break;
    }
  }
  return *this;
}

void RunCounters::add_evaluator(const ContactEvaluator& evaluator) {
  contact_retries += evaluator.retries();
  contact_timeouts += evaluator.timeouts();
  contact_failovers += evaluator.failovers();
  const QueryTimes t = evaluator.query_times();
  bus_round_trip_time += t.round_trip;
  bus_send_time += t.send;
  bus_transfer_time += t.transfer;
  bus_service_wakeup_time += t.service_wakeup;
  bus_compute_time += t.compute;
  bus_reply_time += t.reply;
  bus_client_wakeup_time += t.client_wakeup;
}

}  // namespace wrc
