// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The outputs of a wheelset run: each wheel's contact at an accepted step, the samples every
/// output period (the state interpolated by the integrator, the contact data linearly between the
/// last two accepted steps, no contact evaluation per sample), and the extremes over both.

#include <array>
#include <functional>
#include <vector>

#include "core/dynamics/followed_branches.hpp"
#include "core/dynamics/run_extremes.hpp"
#include "core/dynamics/wheel_forces.hpp"
#include "core/dynamics/wheel_output.hpp"
#include "core/dynamics/wheelset_equations.hpp"

namespace wrc {

/// The contact data of one accepted step.
struct StepContact {
  double t = 0;                       ///< [s]
  std::array<WheelOutput, 2> wheels;  ///< left [0], right [1]
  std::array<WheelForces, 2> forces;  ///< each wheel's patch sums (Y and Q at an output apply its normal force)
};

/// Each wheel's output at the state y (formulation f, followed branches) from its contact c.
StepContact step_contact(const WheelsetEquations& equations, ContactFormulation f, const FollowedBranches& branches,
                         const ContactResult& c, const std::vector<double>& y, double t);

class OutputSampler {
 public:
  /// The state at an output time t [s] within the last step.
  using StateAt = std::function<std::vector<double>(double t)>;
  /// Rigid contact: wheel i's normal force at the state y [N], from its unknowns; empty for
  /// elastic contact (interpolated between the steps like the rest).
  using NormalForce = std::function<double(const double* y, int wheel)>;
  /// One sample: the state y at time t [s] and the wheels there.
  using Sample = std::function<void(const std::vector<double>& y, double t, const std::array<WheelOutput, 2>& wheels)>;

  /// @param period output period [s]; t_end end of the run, always a sample [s]; speed [m/s]
  ///        (distance travelled = speed t).
  OutputSampler(double period, double t_end, double speed) : period_(period), t_end_(t_end), speed_(speed) {}

  /// The first sample at t = 0, no extremes.
  void restart();
  /// The contact of the step just accepted; restart: a new segment starts there (no previous step
  /// to interpolate from).
  void record_step(const StepContact& now, bool restart);
  /// Every sample up to t [s].
  void emit_until(double t, const StateAt& state_at, const NormalForce& rigid_normal_force, const Sample& sample);
  /// The contact of the last accepted step recorded.
  const StepContact& last_step() const { return current_step_; }
  /// The largest values over every accepted step and sample.
  const RunExtremes& extremes() const { return extremes_; }

 private:
  std::array<WheelOutput, 2> wheels_at(double t, const std::vector<double>& y,
                                       const NormalForce& rigid_normal_force) const;

  double period_;
  double t_end_;
  double speed_;
  double next_output_ = 0;
  long output_index_ = 0;
  StepContact previous_step_, current_step_;
  RunExtremes extremes_;
};

}  // namespace wrc
