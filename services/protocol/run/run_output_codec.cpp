#include "protocol/run/run_output_codec.hpp"

#include <exception>

#include "wrc/run_status_t.hpp"

namespace wrc::protocol {
namespace {

// The motion fields every message with a wheelset state has (wheelset_state_t, run_summary_t).
template <class Message>
void copy_motion(const WheelsetSnapshot& s, Message& m) {
  m.y = s.y;
  m.z = s.z;
  m.roll = s.roll;
  m.yaw = s.yaw;
  m.y_dot = s.y_dot;
  m.z_dot = s.z_dot;
  m.roll_dot = s.roll_dot;
  m.yaw_dot = s.yaw_dot;
  m.spin_rate = s.spin_rate;
  for (int i = 0; i < 2; ++i) {
    m.s_wheel[i] = s.wheels[static_cast<std::size_t>(i)].s_wheel;
    m.normal_force[i] = s.wheels[static_cast<std::size_t>(i)].normal_force;
  }
}

}  // namespace

wheelset_state_t to_state_message(const WheelsetSnapshot& s, const std::string& run_id, double speed) {
  wheelset_state_t m{};
  m.run_id = run_id;
  m.t = s.t;
  copy_motion(s, m);
  m.x = speed * s.t;
  m.speed = speed;
  for (int i = 0; i < 2; ++i) m.contact_angle[i] = s.wheels[static_cast<std::size_t>(i)].contact_angle;
  m.model = s.model;
  return m;
}

integrator_stats_t to_stats_message(const RunCounters& c, const std::string& run_id, double t, double wall_time) {
  integrator_stats_t m{};
  m.run_id = run_id;
  m.t = t;
  m.steps = c.steps;
  m.rhs_evals = c.residual_evals;
  m.rhs_evals_jac = c.jacobian_residual_evals;
  m.jac_evals = c.jacobian_evals;
  m.lin_setups = c.lin_setups;
  m.err_test_fails = c.err_test_fails;
  m.nonlin_iters = c.nonlin_iters;
  m.nonlin_conv_fails = c.nonlin_conv_fails;
  m.root_evals = c.root_evals;
  m.root_returns = c.root_returns;
  m.restarts = c.restarts;
  m.contact_switches = c.contact_switches;
  m.last_order = c.last_order;
  m.last_step = c.last_step;
  m.wall_time = wall_time;
  m.contact_queries = c.contact_queries;
  m.contact_configurations = c.contact_configurations;
  m.contact_retries = c.contact_retries;
  m.contact_timeouts = c.contact_timeouts;
  m.missed_switches = c.missed_switches;
  m.two_point_entries = c.two_point_entries;
  m.two_point_time = c.two_point_time;
  m.max_branch_excess = c.max_branch_excess;
  m.floored_patches = c.floored_patches;
  m.floored_time = c.floored_time;
  return m;
}

run_summary_t to_summary_message(WheelsetSimulation& sim, const std::string& run_id, std::int64_t request_id,
                                 double wall_time) {
  run_summary_t m{};
  m.request_id = request_id;
  m.run_id = run_id;
  switch (sim.state()) {
    case RunState::kFinished: m.state = run_status_t::FINISHED; break;
    case RunState::kStopped: m.state = run_status_t::STOPPED; break;
    case RunState::kFailed: m.state = run_status_t::FAILED; break;
    case RunState::kRunning: m.state = run_status_t::RUNNING; break;
  }
  m.message = sim.message();
  m.model = sim.model();
  m.formulation = sim.formulation() == ContactFormulation::kRigid ? "rigid" : "elastic";
  m.t_end = sim.time();
  m.wall_time = wall_time;
  try {
    copy_motion(sim.snapshot(), m);
  } catch (const std::exception& e) {
    if (m.message.empty()) m.message = std::string("final state unavailable: ") + e.what();
  }
  m.stats = to_stats_message(sim.counters(), run_id, sim.time(), wall_time);
  m.num_swaps = static_cast<std::int32_t>(sim.swaps().size());
  for (const SwapRecord& s : sim.swaps()) {
    m.swap_times.push_back(s.t);
    m.swap_models.push_back(s.to);
  }
  return m;
}
}  // namespace wrc::protocol
