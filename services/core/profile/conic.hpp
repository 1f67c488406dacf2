// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A flange-less conical wheel, the simplest test profile: F(s) = -slope * s.

#include <string>

#include "core/profile/profile.hpp"

namespace wrc {

/// Conical wheel: F(s) = -slope * s [m], so the radius decreases towards the field side (s > 0)
/// for slope > 0, like a real tread. No flange. Domain s in [-0.06, 0.06] m.
class ConicProfile final : public Profile {
 public:
  /// @param slope cone slope dF/ds magnitude [-] (e.g. 0.025 for 1:40); any finite value.
  /// @throws std::invalid_argument if slope is not finite.
  explicit ConicProfile(double slope);

  /// Height -slope*s [m], slope -slope [-], second derivative 0 [1/m].
  ProfileSample evaluate(double s) const override;
  /// -0.06 [m].
  double lower() const override;
  /// +0.06 [m].
  double upper() const override;
  /// Always ProfileSide::kWheel.
  ProfileSide side() const override;
  /// "conic:<slope>".
  std::string name() const override;

  /// The cone slope [-].
  double slope() const { return slope_; }

 private:
  double slope_;
};

}  // namespace wrc
