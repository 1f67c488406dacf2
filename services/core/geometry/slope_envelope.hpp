// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Upper bounds of |f'| and |f''| of a function over short bins, for step-size control: a root of
/// g cannot lie closer to s than |g(s)| / max|g'| (the potential-point scan uses this with g the
/// derivative of the distance along C).

#include <functional>
#include <vector>

namespace wrc {

/// Bin-wise maxima of |slope| and |second derivative| of a function on [lower, upper].
class SlopeEnvelope {
 public:
  SlopeEnvelope() = default;
  /// Samples f on `per_bin` points per bin of width `bin` [m] (plus the bin ends) and keeps the
  /// maxima, enlarged by `safety` (> 1) to cover what lies between the samples.
  /// derivatives(x, slope, second) must fill both values at x.
  SlopeEnvelope(double lower, double upper, double bin, int per_bin, double safety,
                const std::function<void(double, double&, double&)>& derivatives);

  bool empty() const { return slope_.empty(); }
  /// Largest |f'| on [a, b] (clamped to the domain) [-].
  double max_slope(double a, double b) const;
  /// Largest |f''| on [a, b] (clamped to the domain) [1/m].
  double max_second(double a, double b) const;
  /// Signed range [low, high] of f'' on [a, b] (clamped to the domain) [1/m].
  void second_range(double a, double b, double& low, double& high) const;

 private:
  int bin_of(double x) const;
  double lower_ = 0, inverse_bin_ = 1;
  std::vector<double> slope_, second_;
  std::vector<double> second_low_, second_high_;
  // runs_[w][i]: the same over bins i .. i + w.
  static constexpr int kRun = 8;
  struct Run {
    std::vector<double> slope, second, low, high;
  };
  Run runs_[kRun];
};

}  // namespace wrc
