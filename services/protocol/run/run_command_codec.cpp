#include "protocol/run/run_command_codec.hpp"

#include <cmath>
#include <stdexcept>

#include "core/models/contact_model_factory.hpp"
#include "protocol/geometry/track_codec.hpp"
#include "wrc/run_status_t.hpp"

namespace wrc::protocol {
namespace {

void require_finite(const char* name, double v) {
  if (!std::isfinite(v)) throw std::invalid_argument(std::string(name) + " = " + std::to_string(v) + " is not finite");
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
  m.track = to_message(r.geometry);
  m.in_process = r.in_process ? 1 : 0;
  const WheelsetParameters& w = r.spec.wheelset;
  m.mass = w.mass;
  m.roll_inertia = w.roll_inertia;
  m.yaw_inertia = w.yaw_inertia;
  m.spin_inertia = w.spin_inertia;
  m.speed = w.speed;
  m.vertical_force = w.vertical_force;
  m.lateral_force = w.lateral_force;
  m.include_gravity = w.include_gravity ? 1 : 0;
  m.gravity = w.gravity;
  const PrimarySuspension& s = w.suspension;
  m.longitudinal_stiffness = s.longitudinal_stiffness;
  m.lateral_stiffness = s.lateral_stiffness;
  m.vertical_stiffness = s.vertical_stiffness;
  m.longitudinal_damping = s.longitudinal_damping;
  m.lateral_damping = s.lateral_damping;
  m.vertical_damping = s.vertical_damping;
  m.half_spacing = s.half_spacing;
  m.shear_modulus = w.material.shear_modulus;
  m.poisson_ratio = w.material.poisson_ratio;
  m.friction = w.material.friction;
  m.fastsim_elements = static_cast<std::int16_t>(w.fastsim_elements);
  m.fastsim_strips = static_cast<std::int16_t>(w.fastsim_strips);
  const InitialState& i = r.spec.initial;
  m.y0 = i.y;
  m.yaw0 = i.yaw;
  m.y_dot0 = i.y_dot;
  m.yaw_dot0 = i.yaw_dot;
  m.spin_rate_offset = i.spin_rate_offset;
  const IntegratorSettings& g = r.spec.integrator;
  m.t_end = g.t_end;
  m.rtol = g.relative_tolerance;
  m.position_tolerance = g.position_tolerance;
  m.velocity_tolerance = g.velocity_tolerance;
  m.max_step = g.max_step;
  m.max_steps = g.max_steps;
  m.output_period = g.output_period;
  m.contact_timeout = r.contact_timeout;
  m.contact_retries = r.contact_retries;
  m.contact_wait = r.contact_wait;
  m.num_scheduled_swaps = static_cast<std::int32_t>(r.swaps.size());
  for (const ScheduledSwap& swap : r.swaps) {
    m.scheduled_swap_times.push_back(swap.t);
    m.scheduled_swap_models.push_back(swap.model);
  }
  return m;
}

RunRequest from_message(const run_command_t& m) {
  RunRequest r;
  r.run_id = m.run_id;
  r.model = m.model;
  contact_model_entry(r.model);  // throws for an unknown model, listing the known ones
  r.instance = m.instance;
  r.geometry = from_message(m.track);
  r.in_process = m.in_process != 0;
  WheelsetParameters& w = r.spec.wheelset;
  w.mass = m.mass;
  w.roll_inertia = m.roll_inertia;
  w.yaw_inertia = m.yaw_inertia;
  w.spin_inertia = m.spin_inertia;
  w.speed = m.speed;
  w.vertical_force = m.vertical_force;
  w.lateral_force = m.lateral_force;
  w.include_gravity = m.include_gravity != 0;
  w.gravity = m.gravity;
  PrimarySuspension& s = w.suspension;
  s.longitudinal_stiffness = m.longitudinal_stiffness;
  s.lateral_stiffness = m.lateral_stiffness;
  s.vertical_stiffness = m.vertical_stiffness;
  s.longitudinal_damping = m.longitudinal_damping;
  s.lateral_damping = m.lateral_damping;
  s.vertical_damping = m.vertical_damping;
  s.half_spacing = m.half_spacing;
  w.material.shear_modulus = m.shear_modulus;
  w.material.poisson_ratio = m.poisson_ratio;
  w.material.friction = m.friction;
  w.fastsim_elements = m.fastsim_elements;
  w.fastsim_strips = m.fastsim_strips;
  InitialState& i = r.spec.initial;
  i.y = m.y0;
  i.yaw = m.yaw0;
  i.y_dot = m.y_dot0;
  i.yaw_dot = m.yaw_dot0;
  i.spin_rate_offset = m.spin_rate_offset;
  IntegratorSettings& g = r.spec.integrator;
  g.t_end = m.t_end;
  g.relative_tolerance = m.rtol;
  g.position_tolerance = m.position_tolerance;
  g.velocity_tolerance = m.velocity_tolerance;
  g.max_step = m.max_step;
  g.max_steps = m.max_steps;
  g.output_period = m.output_period;
  r.spec.validate();
  require_finite("contact_timeout", m.contact_timeout);
  require_finite("contact_wait", m.contact_wait);
  if (!(m.contact_timeout > 0.0 && m.contact_timeout <= 60.0))
    throw std::invalid_argument("contact_timeout = " + std::to_string(m.contact_timeout) + " s is outside (0, 60]");
  if (m.contact_retries < 0 || m.contact_retries > 100)
    throw std::invalid_argument("contact_retries = " + std::to_string(m.contact_retries) + " is outside [0, 100]");
  if (!(m.contact_wait >= 0.0 && m.contact_wait <= 3600.0))
    throw std::invalid_argument("contact_wait = " + std::to_string(m.contact_wait) + " s is outside [0, 3600]");
  r.contact_timeout = m.contact_timeout;
  r.contact_retries = m.contact_retries;
  r.contact_wait = m.contact_wait;
  if (m.num_scheduled_swaps < 0 || m.num_scheduled_swaps > 1000 ||
      static_cast<std::size_t>(m.num_scheduled_swaps) != m.scheduled_swap_times.size() ||
      m.scheduled_swap_models.size() != m.scheduled_swap_times.size())
    throw std::invalid_argument("num_scheduled_swaps = " + std::to_string(m.num_scheduled_swaps) +
                                " does not match the swap lists");
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
  return r;
}
}  // namespace wrc::protocol
