// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/run_extremes.hpp"

#include <cmath>

namespace wrc {

void RunMaximum::observe(double v, double at_t, double at_s) {
  if (std::isnan(v)) return;
  if (std::isnan(t) || v > value) {
    value = v;
    t = at_t;
    distance = at_s;
  }
}

void RunExtremes::observe(double t, double s, const std::array<WheelOutput, 2>& wheels) {
  for (size_t i = 0; i < 2; ++i) {
    y_over_q[i].observe(std::abs(wheels[i].y_over_q()), t, s);
    wear_number[i].observe(wheels[i].wear_number, t, s);
    max_pressure[i].observe(wheels[i].max_pressure, t, s);
  }
  track_shift_force.observe(std::abs(wrc::track_shift_force(wheels[0].lateral_force, wheels[1].lateral_force)), t, s);
}

void RunExtremes::observe_step(double t, double s, const std::array<WheelOutput, 2>& wheels) {
  observe(t, s, wheels);
  for (size_t i = 0; i < 2; ++i) {
    y_over_q_means_[i].add(s, t, wheels[i].y_over_q(), [&](const DistanceSlidingMean::Mean& m) {
      y_over_q_2m[i].observe(std::abs(m.value), m.t, m.distance);
    });
  }
  track_shift_force_means_.add(s, t, wrc::track_shift_force(wheels[0].lateral_force, wheels[1].lateral_force),
                               [&](const DistanceSlidingMean::Mean& m) {
                                 track_shift_force_2m.observe(std::abs(m.value), m.t, m.distance);
                               });
}

}  // namespace wrc
