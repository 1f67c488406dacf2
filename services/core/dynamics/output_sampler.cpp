// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/output_sampler.hpp"

#include <algorithm>
#include <limits>

namespace wrc {

StepContact step_contact(const WheelsetEquations& equations, ContactFormulation f, const FollowedBranches& branches,
                         const ContactResult& c, const std::vector<double>& y, double t) {
  StepContact out{t, {}, {}};
  for (int i = 0; i < 2; ++i) {
    WheelOutput& w = out.wheels[static_cast<size_t>(i)];
    w.s_wheel = c.wheels[static_cast<size_t>(i)].s_wheel;
    w.contact_angle = c.wheels[static_cast<size_t>(i)].contact_angle;
    w.normal_force = equations.normal_force(f, y.data(), c, i, branches);
    // The wheel's normal force: rigid, the constraint's multiplier, which a spline transition
    // shares over two patches (their normal forces add up to it as vectors, not as magnitudes);
    // elastic, the patches' own sum, what wheel_forces() takes by default.
    const WheelForces forces = w.normal_force > 0.0 ? wheel_forces(c, i, w.normal_force) : wheel_forces(c, i);
    set_force_outputs(forces, w.normal_force, i, w);
    out.forces[static_cast<size_t>(i)] = forces;
  }
  return out;
}

void OutputSampler::restart() {
  next_output_ = 0.0;
  output_index_ = 0;
  extremes_ = RunExtremes{};
}

void OutputSampler::record_step(const StepContact& now, bool restart) {
  previous_step_ = restart ? now : current_step_;
  current_step_ = now;
  extremes_.observe_step(now.t, speed_ * now.t, now.wheels);
}

std::array<WheelOutput, 2> OutputSampler::wheels_at(double t, const std::vector<double>& y,
                                                    const NormalForce& rigid_normal_force) const {
  const double span = current_step_.t - previous_step_.t;
  const double w = span > 0.0 ? std::clamp((t - previous_step_.t) / span, 0.0, 1.0) : 1.0;
  std::array<WheelOutput, 2> wheels;
  for (size_t i = 0; i < 2; ++i) {
    const WheelOutput& a = previous_step_.wheels[i];
    const WheelOutput& b = current_step_.wheels[i];
    wheels[i].s_wheel = a.s_wheel + w * (b.s_wheel - a.s_wheel);
    wheels[i].contact_angle = a.contact_angle + w * (b.contact_angle - a.contact_angle);
    wheels[i].normal_force = rigid_normal_force ? rigid_normal_force(y.data(), static_cast<int>(i))
                                                : a.normal_force + w * (b.normal_force - a.normal_force);
    set_force_outputs(interpolate(previous_step_.forces[i], current_step_.forces[i], w), wheels[i].normal_force,
                      static_cast<int>(i), wheels[i]);
  }
  return wheels;
}

void OutputSampler::emit_until(double t, const StateAt& state_at, const NormalForce& rigid_normal_force,
                               const Sample& sample) {
  while (next_output_ <= t) {
    const std::vector<double> y = state_at(next_output_);
    const std::array<WheelOutput, 2> wheels = wheels_at(next_output_, y, rigid_normal_force);
    extremes_.observe(next_output_, speed_ * next_output_, wheels);
    if (sample) sample(y, next_output_, wheels);
    if (next_output_ >= t_end_) {
      next_output_ = std::numeric_limits<double>::infinity();
      break;
    }
    ++output_index_;
    next_output_ = std::min(t_end_, static_cast<double>(output_index_) * period_);
  }
}

}  // namespace wrc
