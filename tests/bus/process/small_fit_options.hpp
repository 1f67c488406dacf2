// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A spline model that wrc-geometryd fits in well under a second, for the bus tests that need a
/// fit: cubic in y on 4 intervals, linear in roll and yaw, 3 x 3 lines sampled every 0.5 mm.

#include "core/spline/spline_fit_options.hpp"

namespace wrc::bus::test {

inline SplineFitOptions small_fit_options() {
  SplineFitOptions o;
  o.intervals = {4, 1, 1};
  o.degrees = {3, 1, 1};
  o.roll_samples = 3;
  o.yaw_samples = 3;
  o.sample_step_y = 5e-4;
  return o;
}

}  // namespace wrc::bus::test
