// SPDX-License-Identifier: Apache-2.0
#include "core/profile/spline_profile.hpp"

#include <utility>

namespace wrc {
namespace {

// Knots at least min_spacing apart; the last point is always kept (it replaces the last kept
// point if those two are too close).
CubicSpline thinned_spline(const ProfilePoints& p, double min_spacing) {
  std::vector<double> x{p.lateral.front()};
  std::vector<double> y{p.height.front()};
  const std::size_t n = p.lateral.size();
  for (std::size_t i = 1; i < n; ++i) {
    if (p.lateral[i] - x.back() >= min_spacing) {
      x.push_back(p.lateral[i]);
      y.push_back(p.height[i]);
    } else if (i == n - 1) {
      if (x.size() > 1) {
        x.back() = p.lateral[i];
        y.back() = p.height[i];
      } else {
        x.push_back(p.lateral[i]);
        y.push_back(p.height[i]);
      }
    }
  }
  if (x.size() < 3) {
    // A very narrow point set: interpolate every point rather than fail.
    return CubicSpline(p.lateral, p.height);
  }
  return CubicSpline(std::move(x), y);
}

}  // namespace

SplineProfile::SplineProfile(const ProfilePoints& points, ProfileSide side, std::string name,
                             double built_in_cant, double min_spacing)
    : points_(points),
      spline_(thinned_spline(points, min_spacing)),
      side_(side),
      name_(std::move(name)),
      built_in_cant_(built_in_cant) {}

ProfileSample SplineProfile::evaluate(double s) const {
  const SplineSample sample = spline_.evaluate(s);
  return {sample.value, sample.slope, sample.second_derivative};
}
double SplineProfile::lower() const { return points_.lateral.front(); }
double SplineProfile::upper() const { return points_.lateral.back(); }

}  // namespace wrc
