// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/contact_model_options.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/geometry/wheelset_geometry.hpp"

namespace wrc {
namespace {

void require_count(int value, const char* name, int low, int high, bool odd = false) {
  if (value >= low && value <= high && (!odd || value % 2 == 1)) return;
  std::ostringstream msg;
  msg << "interpolation grid: " << name << " = " << value << " must be " << (odd ? "odd and " : "") << "in " << low
      << ".." << high;
  throw std::invalid_argument(msg.str());
}

void require_positive(double value, const char* where, const char* name, const char* unit) {
  if (value > 0.0 && std::isfinite(value)) return;
  std::ostringstream msg;
  msg << where << ": " << name << " = " << value << " " << unit << " must be positive and finite";
  throw std::invalid_argument(msg.str());
}

void require_within(double value, const char* name, const char* unit, double low, double high) {
  if (value >= low && value <= high) return;
  std::ostringstream msg;
  msg << "interpolation grid: " << name << " = " << value << " " << unit << " must be in [" << low << ", " << high
      << "] " << unit;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void InterpolationGrid::validate() const {
  require_count(y_points, "y_points", 2, 10000);
  require_count(roll_points, "roll_points", 3, 9, true);
  require_count(yaw_points, "yaw_points", 2, 9);
  require_positive(y_max, "interpolation grid", "y_max", "m");
  require_positive(roll_band, "interpolation grid", "roll_band", "rad");
  require_positive(roll_max, "interpolation grid", "roll_max", "rad");
  require_positive(yaw_max, "interpolation grid", "yaw_max", "rad");
  if (yaw_max > kMaxValidatedYaw) {
    std::ostringstream msg;
    msg << "interpolation grid: yaw_max = " << yaw_max << " rad is beyond the validated range "
        << kMaxValidatedYaw << " rad of the contact geometry";
    throw std::invalid_argument(msg.str());
  }
  require_within(transition, "transition", "m", 0.0, kMaxTransition);
  require_within(transition_load, "transition_load", "N", kMinTransitionLoad, kMaxTransitionLoad);
}

void ContactModelOptions::validate() const {
  if (!(lateral_curvature_floor >= 0.0) || !std::isfinite(lateral_curvature_floor)) {
    std::ostringstream msg;
    msg << "contact model options: lateral_curvature_floor = " << lateral_curvature_floor
        << " must be non-negative and finite";
    throw std::invalid_argument(msg.str());
  }
  require_positive(search.step, "contact model options", "search.step", "m");
  require_positive(search.tolerance, "contact model options", "search.tolerance", "m");
  interp.validate();
}

}  // namespace wrc
