// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The contact-point branches a rigid-contact run follows on each wheel: the point of one-point
/// contact, and while a wheel slides on a switching surface (two minima of the distance equally
/// low) the second point of its rigid two-point contact (docs/dynamics.md, "Contact-point jumps").

#include <array>
#include <cmath>
#include <limits>

namespace wrc {

struct FollowedBranches {
  /// Wheel profile coordinate of the followed point of the left [0] and right [1] wheel [m]; NaN:
  /// the model's own choice (the lowest minimum).
  std::array<double, 2> tracked_s{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  /// The second point of a wheel in rigid two-point contact [m]; NaN: one-point contact.
  std::array<double, 2> second_s{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};

  bool two_point(int wheel) const { return !std::isnan(second_s[static_cast<std::size_t>(wheel)]); }
  bool any_two_point() const { return two_point(0) || two_point(1); }
};

}  // namespace wrc
