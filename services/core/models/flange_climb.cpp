// SPDX-License-Identifier: Apache-2.0
#include "core/models/flange_climb.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/model_interface/contact_model.hpp"
#include "core/models/one_point_model.hpp"

namespace wrc {

double steepest_flange_point(const Profile& wheel) {
  const double lo = wheel.lower(), hi = std::min(0.0, wheel.upper());
  if (!(hi > lo)) return lo;
  const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / 1e-5)));
  double best_s = lo, best_rise = -wheel.evaluate(lo).slope;
  for (int i = 1; i <= n; ++i) {
    const double s = lo + (hi - lo) * i / n;
    const double rise = -wheel.evaluate(s).slope;
    if (rise > best_rise * (1 + 1e-12) + 1e-15) {
      best_rise = rise;
      best_s = s;
    }
  }
  return best_s;
}

void check_flange_not_climbed(const ContactPoint& point, double steepest, const WheelsetPose& pose) {
  if (!(point.s < steepest && point.contact_angle < kFlangeClimbAngle)) return;
  std::ostringstream msg;
  msg << "the " << side_name(point.side) << " wheel's flange has climbed onto its rail: contact at s = " << point.s
      << " m beyond the steepest flange point s = " << steepest << " m with contact angle " << point.contact_angle
      << " rad < 20 deg, at " << describe_pose(pose);
  throw ContactConfigurationError(msg.str());
}

}  // namespace wrc
