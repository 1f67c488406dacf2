// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/run_command_codec.hpp"

#include <cmath>
#include <stdexcept>

#include "core/models/contact_model_factory.hpp"
#include "protocol/geometry/fit_options_codec.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "protocol/message_fields.hpp"
#include "protocol/run/run_request_table.hpp"
#include "protocol/run/irregularity_codec.hpp"
#include "protocol/run/track_layout_codec.hpp"
#include "protocol/run/vehicle_codec.hpp"
#include "wrc/run_status_t.hpp"

namespace wrc::protocol {
namespace {

// The field of each run_request_table() key (protocol/message_fields.hpp).
const std::vector<MessageField<run_command_t>>& run_command_fields() {
  using M = run_command_t;
  static const std::vector<MessageField<M>> fields{
      WRC_MESSAGE_FIELD(M, mass), WRC_MESSAGE_FIELD(M, roll_inertia), WRC_MESSAGE_FIELD(M, yaw_inertia),
      WRC_MESSAGE_FIELD(M, spin_inertia), WRC_MESSAGE_FIELD(M, speed), WRC_MESSAGE_FIELD(M, vertical_force),
      WRC_MESSAGE_FIELD(M, lateral_force), WRC_MESSAGE_FIELD(M, include_gravity), WRC_MESSAGE_FIELD(M, gravity),
      WRC_MESSAGE_FIELD(M, longitudinal_stiffness), WRC_MESSAGE_FIELD(M, lateral_stiffness),
      WRC_MESSAGE_FIELD(M, vertical_stiffness), WRC_MESSAGE_FIELD(M, longitudinal_damping),
      WRC_MESSAGE_FIELD(M, lateral_damping), WRC_MESSAGE_FIELD(M, vertical_damping), WRC_MESSAGE_FIELD(M, half_spacing),
      WRC_MESSAGE_FIELD(M, shear_modulus), WRC_MESSAGE_FIELD(M, poisson_ratio), WRC_MESSAGE_FIELD(M, friction),
      WRC_MESSAGE_FIELD(M, fastsim_elements), WRC_MESSAGE_FIELD(M, fastsim_strips), WRC_MESSAGE_FIELD(M, flange_angle), WRC_MESSAGE_FIELD(M, y0),
      WRC_MESSAGE_FIELD(M, yaw0), WRC_MESSAGE_FIELD(M, y_dot0), WRC_MESSAGE_FIELD(M, yaw_dot0),
      WRC_MESSAGE_FIELD(M, spin_rate_offset), WRC_MESSAGE_FIELD(M, t_end), WRC_MESSAGE_FIELD(M, rtol),
      WRC_MESSAGE_FIELD(M, position_tolerance), WRC_MESSAGE_FIELD(M, velocity_tolerance),
      WRC_MESSAGE_FIELD(M, max_step), WRC_MESSAGE_FIELD(M, max_steps), WRC_MESSAGE_FIELD(M, output_period),
      WRC_MESSAGE_FIELD(M, two_point_sliding),
      WRC_MESSAGE_FIELD(M, contact_timeout), WRC_MESSAGE_FIELD(M, contact_retries),
      WRC_MESSAGE_FIELD(M, contact_wait),
  };
  return fields;
}

}  // namespace

const char* run_state_name(std::int8_t state) {
  switch (state) {
    case run_status_t::IDLE: return "idle";
    case run_status_t::RUNNING: return "running";
    case run_status_t::FINISHED: return "finished";
    case run_status_t::FAILED: return "failed";
    case run_status_t::STOPPED: return "stopped";
  }
  return "unknown";
}

run_command_t to_message(const RunRequest& r) {
  run_command_t m{};
  m.run_id = r.run_id;
  m.command = run_command_t::START;
  m.model = r.model;
  m.instance = r.instance;
  m.dynamics_instance = r.dynamics_instance;
  m.track = to_message(r.geometry);
  m.in_process = r.in_process ? 1 : 0;
  to_message_fields(run_request_table(), r, run_command_fields(), m);
  to_layout_fields(r.spec.track, m);
  to_irregularity_fields(r.spec.irregularity, m);
  to_vehicle_fields(r.vehicle, m);
  m.num_scheduled_swaps = static_cast<std::int32_t>(r.swaps.size());
  for (const ScheduledSwap& swap : r.swaps) {
    m.scheduled_swap_times.push_back(swap.t);
    m.scheduled_swap_models.push_back(swap.model);
  }
  m.spline_fit = to_message(r.spline_fit);
  return m;
}

RunRequest from_message(const run_command_t& m) {
  if (m.in_process != 0 && m.in_process != 1)
    throw std::invalid_argument("in_process = " + std::to_string(m.in_process) + " is neither 0 nor 1");
  RunRequest r;
  r.run_id = m.run_id;
  r.model = m.model;
  contact_model_entry(r.model);  // throws for an unknown model, listing the known ones
  r.instance = m.instance;
  r.dynamics_instance = m.dynamics_instance;
  r.geometry = from_message(m.track);
  r.in_process = m.in_process == 1;
  from_message_fields(run_request_table(), m, run_command_fields(), r);
  r.spec.track = layout_from_fields(m);
  r.spec.irregularity = irregularity_from_fields(m);
  r.vehicle = vehicle_from_fields(m);
  r.spec.validate();  // the rules between parameters
  const IntegratorSettings& g = r.spec.integrator;
  const std::string swaps = "num_scheduled_swaps = " + std::to_string(m.num_scheduled_swaps);
  if (m.num_scheduled_swaps < 0) throw std::invalid_argument(swaps + " is negative");
  if (static_cast<std::size_t>(m.num_scheduled_swaps) > kMaxScheduledSwaps)
    throw std::invalid_argument(swaps + " is more than the limit of " + std::to_string(kMaxScheduledSwaps) +
                                " scheduled swaps");
  if (static_cast<std::size_t>(m.num_scheduled_swaps) != m.scheduled_swap_times.size() ||
      m.scheduled_swap_models.size() != m.scheduled_swap_times.size())
    throw std::invalid_argument(swaps + " does not match the swap lists (" +
                                std::to_string(m.scheduled_swap_times.size()) + " times, " +
                                std::to_string(m.scheduled_swap_models.size()) + " models)");
  double last = 0.0;
  for (std::size_t k = 0; k < m.scheduled_swap_times.size(); ++k) {
    const double t = m.scheduled_swap_times[k];
    if (!(std::isfinite(t) && t > last && t < g.t_end))
      throw std::invalid_argument("scheduled_swap_times[" + std::to_string(k) + "] = " + std::to_string(t) +
                                  " s is not increasing within (0, t_end)");
    contact_model_entry(m.scheduled_swap_models[k]);
    r.swaps.push_back({t, m.scheduled_swap_models[k]});
    last = t;
  }
  try {
    r.spline_fit = from_message(m.spline_fit);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("spline_fit: ") + e.what());
  }
  return r;
}
}  // namespace wrc::protocol
