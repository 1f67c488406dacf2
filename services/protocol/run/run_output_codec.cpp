// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/run_output_codec.hpp"

#include <exception>

#include "core/dynamics/run_counter_table.hpp"
#include "core/dynamics/safety_limits.hpp"
#include "protocol/message_fields.hpp"
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

run_maximum_t to_message(const RunMaximum& m) {
  run_maximum_t out{};
  out.value = m.value;
  out.t = m.t;
  out.distance = m.distance;
  return out;
}

// The maxima of what engineers read off a wheelset's run, and the axle load and Prud'homme's limit
// they are judged against (run_summary_t, wheelset_summary_t).
template <class Message>
void copy_extremes(const RunExtremes& e, const WheelsetParameters& p, Message& m) {
  for (std::size_t i = 0; i < 2; ++i) {
    m.max_y_over_q[i] = to_message(e.y_over_q[i]);
    m.max_wear_number[i] = to_message(e.wear_number[i]);
    m.max_pressure[i] = to_message(e.max_pressure[i]);
    m.max_y_over_q_2m[i] = to_message(e.y_over_q_2m[i]);
  }
  m.max_track_shift_force = to_message(e.track_shift_force);
  m.max_track_shift_force_2m = to_message(e.track_shift_force_2m);
  m.axle_load = p.total_vertical_load();
  m.prudhomme_limit = prudhomme_limit(m.axle_load);
}

// Nadal's limit of the run (its flange angle and friction).
void copy_nadal(const WheelsetParameters& p, run_summary_t& m) {
  m.flange_angle = p.flange_angle;
  m.nadal_limit = nadal_limit(p.flange_angle, p.material.friction);
}

// What every summary says of the run as a whole.
void copy_run(const Simulation& sim, const std::string& run_id, std::int64_t request_id, double wall_time,
              run_summary_t& m) {
  m.request_id = request_id;
  m.run_id = run_id;
  m.state = run_state_code(sim.state());
  m.message = sim.message();
  m.model = sim.model();
  m.t_end = sim.time();
  m.wall_time = wall_time;
  m.stats = to_stats_message(sim.counters(), run_id, sim.time(), wall_time);
  m.num_swaps = static_cast<std::int32_t>(sim.swaps().size());
  for (const SwapRecord& s : sim.swaps()) {
    m.swap_times.push_back(s.t);
    m.swap_models.push_back(s.to);
  }
}

// The field of each run_counter_table() name; three kept the message's older names.
const std::vector<MessageField<integrator_stats_t>>& stats_fields() {
  using M = integrator_stats_t;
  static const std::vector<MessageField<M>> fields{
      WRC_MESSAGE_FIELD(M, steps),
      message_field("residual_evals", &M::rhs_evals),
      message_field("jacobian_evals", &M::jac_evals),
      message_field("jacobian_residual_evals", &M::rhs_evals_jac),
      WRC_MESSAGE_FIELD(M, lin_setups),
      WRC_MESSAGE_FIELD(M, err_test_fails),
      WRC_MESSAGE_FIELD(M, nonlin_iters),
      WRC_MESSAGE_FIELD(M, nonlin_conv_fails),
      WRC_MESSAGE_FIELD(M, root_evals),
      WRC_MESSAGE_FIELD(M, root_returns),
      WRC_MESSAGE_FIELD(M, restarts),
      WRC_MESSAGE_FIELD(M, convergence_restarts),
      WRC_MESSAGE_FIELD(M, contact_switches),
      WRC_MESSAGE_FIELD(M, missed_switches),
      WRC_MESSAGE_FIELD(M, two_point_entries),
      WRC_MESSAGE_FIELD(M, two_point_time),
      WRC_MESSAGE_FIELD(M, max_branch_excess),
      WRC_MESSAGE_FIELD(M, floored_patches),
      WRC_MESSAGE_FIELD(M, floored_time),
      WRC_MESSAGE_FIELD(M, contact_queries),
      WRC_MESSAGE_FIELD(M, contact_configurations),
      WRC_MESSAGE_FIELD(M, contact_sent_ahead),
      WRC_MESSAGE_FIELD(M, contact_ahead_used),
      WRC_MESSAGE_FIELD(M, contact_retries),
      WRC_MESSAGE_FIELD(M, contact_timeouts),
      WRC_MESSAGE_FIELD(M, contact_failovers),
      WRC_MESSAGE_FIELD(M, bus_round_trip_time),
      WRC_MESSAGE_FIELD(M, bus_send_time),
      WRC_MESSAGE_FIELD(M, bus_transfer_time),
      WRC_MESSAGE_FIELD(M, bus_service_wakeup_time),
      WRC_MESSAGE_FIELD(M, bus_compute_time),
      WRC_MESSAGE_FIELD(M, bus_reply_time),
      WRC_MESSAGE_FIELD(M, bus_client_wakeup_time),
      WRC_MESSAGE_FIELD(M, last_order),
      WRC_MESSAGE_FIELD(M, last_step),
  };
  return fields;
}

}  // namespace

std::int8_t run_state_code(RunState state) {
  switch (state) {
    case RunState::kRunning: return run_status_t::RUNNING;
    case RunState::kFinished: return run_status_t::FINISHED;
    case RunState::kFailed: return run_status_t::FAILED;
    case RunState::kStopped: return run_status_t::STOPPED;
  }
  return run_status_t::FAILED;
}

wheelset_state_t to_state_message(const WheelsetSnapshot& s, const std::string& run_id, const WheelsetParameters& w,
                                  int wheelset, double ahead) {
  const double speed = w.speed;
  wheelset_state_t m{};
  m.run_id = run_id;
  m.wheelset = static_cast<std::int16_t>(wheelset);
  m.t = s.t;
  copy_motion(s, m);
  m.x = speed * s.t + ahead;
  m.speed = speed;
  for (std::size_t i = 0; i < 2; ++i) {
    const WheelOutput& wheel = s.wheels[i];
    m.contact_angle[i] = wheel.contact_angle;
    m.lateral_force[i] = wheel.lateral_force;
    m.vertical_force[i] = wheel.vertical_force;
    m.creep_force_x[i] = wheel.creep_force_x;
    m.creep_force_y[i] = wheel.creep_force_y;
    m.wear_number[i] = wheel.wear_number;
    m.max_pressure[i] = wheel.max_pressure;
  }
  m.nadal_limit = nadal_limit(w.flange_angle, w.material.friction);
  m.prudhomme_limit = prudhomme_limit(w.total_vertical_load());
  m.model = s.model;
  return m;
}

integrator_stats_t to_stats_message(const RunCounters& c, const std::string& run_id, double t, double wall_time) {
  integrator_stats_t m{};
  m.run_id = run_id;
  m.t = t;
  m.wall_time = wall_time;
  to_message_fields(run_counter_table(), c, stats_fields(), m);
  return m;
}

RunCounters from_stats_message(const integrator_stats_t& m) {
  RunCounters c;
  for (const RunCounter& counter : run_counter_table()) counter.set(c, field_of(stats_fields(), counter.key).get(m));
  return c;
}

run_summary_t to_summary_message(WheelsetSimulation& sim, const std::string& run_id, std::int64_t request_id,
                                 double wall_time) {
  run_summary_t m{};
  // The final state first: its contact may be one more query, which the counters then hold.
  std::string unavailable;
  try {
    copy_motion(sim.snapshot(), m);
  } catch (const std::exception& e) {
    unavailable = std::string("final state unavailable: ") + e.what();
  }
  copy_run(sim, run_id, request_id, wall_time, m);
  if (m.message.empty()) m.message = unavailable;
  m.formulation = sim.formulation() == ContactFormulation::kRigid ? "rigid" : "elastic";
  copy_extremes(sim.extremes(), sim.spec().wheelset, m);
  copy_nadal(sim.spec().wheelset, m);
  return m;
}

run_summary_t to_summary_message(VehicleSimulation& sim, const std::string& run_id, std::int64_t request_id,
                                 double wall_time) {
  run_summary_t m{};
  const VehicleEquations& e = sim.equations();
  copy_nadal(sim.wheelset_parameters(0), m);
  std::string unavailable;
  try {
    const VehicleSnapshot now = sim.snapshot();
    for (size_t w = 0; w < e.wheelset_count(); ++w) {
      WheelsetSnapshot final_state = sim.wheelset_snapshot(now, w);
      final_state.wheels = sim.last_step_wheels(w);  // the snapshot has no wheels: the last accepted step's
      wheelset_summary_t ws{};
      ws.name = e.vehicle().bodies[e.wheelset_body(w)].name;
      copy_motion(final_state, ws);
      copy_extremes(sim.extremes(w), sim.wheelset_parameters(w), ws);
      m.wheelsets.push_back(ws);
      if (w == 0) {  // the first wheelset also in the lone wheelset's fields
        copy_motion(final_state, m);
        copy_extremes(sim.extremes(0), sim.wheelset_parameters(0), m);
      }
    }
  } catch (const std::exception& ex) {
    unavailable = std::string("final state unavailable: ") + ex.what();
  }
  // After the final state, whose contact may be one more query.
  copy_run(sim, run_id, request_id, wall_time, m);
  if (m.message.empty()) m.message = unavailable;
  m.formulation = sim.formulation() == ContactFormulation::kRigid ? "rigid" : "elastic";
  m.num_wheelsets = static_cast<std::int16_t>(m.wheelsets.size());
  for (size_t b = 0; b < e.vehicle().bodies.size(); ++b) {
    if (e.wheelset_of_body(b) >= 0) continue;
    body_summary_t body{};
    body.name = e.vehicle().bodies[b].name;
    body.max_lateral_acceleration = to_message(sim.acceleration_maxima(b).lateral);
    body.max_vertical_acceleration = to_message(sim.acceleration_maxima(b).vertical);
    m.bodies.push_back(body);
  }
  m.num_bodies = static_cast<std::int16_t>(m.bodies.size());
  return m;
}

}  // namespace wrc::protocol
