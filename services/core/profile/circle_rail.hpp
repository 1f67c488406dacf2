// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A circular rail head, the simplest rail test profile: v(u) = sqrt(R^2 - u^2) - R.

#include <string>

#include "core/profile/profile.hpp"

namespace wrc {

/// Circular rail head of radius R [m], top at the origin. Domain |u| <= min(0.036, 0.9 R) [m],
/// which keeps the slope below about 2.06 (64 degrees) and away from the vertical tangent.
class CircleRailProfile final : public Profile {
 public:
  /// @param radius head radius R [m], > 0 and finite.
  /// @throws std::invalid_argument otherwise.
  explicit CircleRailProfile(double radius);

  /// Height [m], slope [-], second derivative [1/m] of the circle.
  ProfileSample evaluate(double u) const override;
  /// -min(0.036, 0.9 R) [m].
  double lower() const override;
  /// +min(0.036, 0.9 R) [m].
  double upper() const override;
  /// Always ProfileSide::kRail.
  ProfileSide side() const override;
  /// "circle:<radius>".
  std::string name() const override;

  /// Head radius [m].
  double radius() const { return radius_; }

 private:
  double radius_;
  double half_width_;
};

}  // namespace wrc
