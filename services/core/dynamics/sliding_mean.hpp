// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The sliding mean of a quantity over the distance travelled, as EN 14363 assesses the track-shift
/// force sum Y and Y/Q (docs/run-quantities.md, "Sliding means"): the mean over a window of 2 m
/// of track, taken at window ends 0.5 m apart. A run's samples come at its accepted steps, unevenly
/// spaced in distance; the quantity is taken as linear between them, so each window's mean is the
/// exact integral of that interpolant over the window divided by its length.

#include <deque>
#include <functional>

namespace wrc {

/// EN 14363's window of the sliding means of sum Y and Y/Q [m].
inline constexpr double kSlidingMeanWindow = 2.0;
/// EN 14363's interval between the ends of successive windows [m].
inline constexpr double kSlidingMeanInterval = 0.5;

class DistanceSlidingMean {
 public:
  /// One window's mean.
  struct Mean {
    double distance = 0;  ///< the window's end, a multiple of the interval [m]
    double t = 0;         ///< the time at the window's end, interpolated between the samples [s]
    double value = 0;     ///< the mean over the window [unit of the quantity]
  };
  using OnMean = std::function<void(const Mean&)>;

  /// @param window length of the window [m] > 0; interval between window ends [m] > 0.
  /// @throws std::invalid_argument naming a value that is not finite and > 0.
  explicit DistanceSlidingMean(double window = kSlidingMeanWindow, double interval = kSlidingMeanInterval);

  /// Adds the sample v [unit] at distance s [m] and time t [s] and reports, in order, the mean of
  /// every window whose end it passed (s_previous < end <= s) and that lies wholly after the first
  /// sample. Samples come with s not decreasing; two at the same distance (a restart's jump) make
  /// the interpolant jump there. A non-finite v or s is skipped (the interpolant bridges it).
  /// @throws std::invalid_argument when s is less than the last sample's.
  void add(double s, double t, double v, const OnMean& on_mean);
  /// Forgets every sample (a new run).
  void clear();

 private:
  struct Sample {
    double s, t, v;
  };
  /// The integral of the interpolant from distance a to b (both within the samples held) [unit m].
  double integral(double a, double b) const;
  Sample at(double s) const;

  double window_;
  double interval_;
  double first_s_ = 0;
  bool started_ = false;
  std::deque<Sample> samples_;  // every sample from the one at or before (latest end - window) on
};

}  // namespace wrc
