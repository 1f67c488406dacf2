#include "protocol/geometry/fit_options_codec.hpp"

#include <stdexcept>
#include <string>

namespace wrc::protocol {

spline_fit_options_t to_message(const SplineFitOptions& o) {
  spline_fit_options_t m;
  m.y_min = o.y_min;
  m.y_max = o.y_max;
  m.roll_max = o.roll_max;
  m.yaw_max = o.yaw_max;
  for (int k = 0; k < 3; ++k) {
    m.intervals[k] = o.intervals[static_cast<size_t>(k)];
    m.degrees[k] = static_cast<int8_t>(o.degrees[static_cast<size_t>(k)]);
  }
  m.knot_placement =
      o.placement == KnotPlacement::kUniform ? spline_fit_options_t::UNIFORM : spline_fit_options_t::GRADED;
  m.grading = o.grading;
  m.num_y_breakpoints = static_cast<int32_t>(o.y_breakpoints.size());
  m.y_breakpoints = o.y_breakpoints;
  m.sample_step_y = o.sample_step_y;
  m.roll_samples = o.roll_samples;
  m.yaw_samples = o.yaw_samples;
  m.jump_weight = o.jump_weight;
  m.jump_band = o.jump_band;
  m.transition = o.transition;
  m.flange_angle = o.flange_angle;
  m.clearance_cap = o.clearance_cap;
  return m;
}

SplineFitOptions from_message(const spline_fit_options_t& m) {
  SplineFitOptions o;
  o.y_min = m.y_min;
  o.y_max = m.y_max;
  o.roll_max = m.roll_max;
  o.yaw_max = m.yaw_max;
  for (int k = 0; k < 3; ++k) {
    o.intervals[static_cast<size_t>(k)] = m.intervals[k];
    o.degrees[static_cast<size_t>(k)] = m.degrees[k];
  }
  if (m.knot_placement != spline_fit_options_t::UNIFORM && m.knot_placement != spline_fit_options_t::GRADED)
    throw std::invalid_argument("spline_fit_options_t: knot_placement = " + std::to_string(m.knot_placement) +
                                " is neither UNIFORM (0) nor GRADED (1)");
  o.placement = m.knot_placement == spline_fit_options_t::UNIFORM ? KnotPlacement::kUniform : KnotPlacement::kGraded;
  o.grading = m.grading;
  if (m.num_y_breakpoints < 0 || static_cast<size_t>(m.num_y_breakpoints) != m.y_breakpoints.size())
    throw std::invalid_argument("spline_fit_options_t: num_y_breakpoints = " + std::to_string(m.num_y_breakpoints) +
                                " does not match the array");
  o.y_breakpoints = m.y_breakpoints;
  o.sample_step_y = m.sample_step_y;
  o.roll_samples = m.roll_samples;
  o.yaw_samples = m.yaw_samples;
  o.jump_weight = m.jump_weight;
  o.jump_band = m.jump_band;
  o.transition = m.transition;
  o.flange_angle = m.flange_angle;
  o.clearance_cap = m.clearance_cap;
  o.validate();
  return o;
}
}  // namespace wrc::protocol
