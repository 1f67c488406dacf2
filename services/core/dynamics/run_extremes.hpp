// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The largest values of what engineers read off a run (docs/run-quantities.md), each with where it
/// occurred: |Y/Q| per wheel, |sum Y| of the axle, T gamma and p_max per wheel, and EN 14363's
/// largest 2 m sliding means of Y/Q and sum Y.

#include <array>
#include <limits>

#include "core/dynamics/sliding_mean.hpp"
#include "core/dynamics/wheel_output.hpp"

namespace wrc {

/// The largest value of one quantity seen so far and where.
struct RunMaximum {
  double value = 0;                                      ///< in the quantity's unit; 0 before any sample
  double t = std::numeric_limits<double>::quiet_NaN();   ///< simulated time where it occurred [s] (NaN: none yet)
  double distance = std::numeric_limits<double>::quiet_NaN();  ///< distance travelled there, speed t [m]
  /// Keeps v [unit] at time t [s] and distance travelled s [m] when it exceeds the value held (NaN
  /// is skipped; the first of equal values is kept).
  void observe(double v, double t, double s);
};

/// The maxima over every sample observe() was given (the run: every accepted step and every output).
struct RunExtremes {
  std::array<RunMaximum, 2> y_over_q;      ///< |Y/Q| of the left [0] and right [1] wheel [-] (Q > 0 only)
  RunMaximum track_shift_force;            ///< |sum Y| = |Y_left - Y_right| of the axle [N]
  std::array<RunMaximum, 2> wear_number;   ///< T gamma per wheel [N]
  std::array<RunMaximum, 2> max_pressure;  ///< p_max per wheel [Pa]

  /// The largest |2 m sliding mean| of Y/Q per wheel [-] and of sum Y [N] (EN 14363: windows of
  /// kSlidingMeanWindow ending every kSlidingMeanInterval of distance, over the accepted steps);
  /// where: the window's end.
  std::array<RunMaximum, 2> y_over_q_2m;
  RunMaximum track_shift_force_2m;
  /// One sample: the wheels at time t [s], distance travelled s [m].
  void observe(double t, double s, const std::array<WheelOutput, 2>& wheels);
  /// An accepted step's sample (distance not decreasing): observe() and the sliding means.
  void observe_step(double t, double s, const std::array<WheelOutput, 2>& wheels);

 private:
  std::array<DistanceSlidingMean, 2> y_over_q_means_;
  DistanceSlidingMean track_shift_force_means_;
};

}  // namespace wrc
