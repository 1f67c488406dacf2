// SPDX-License-Identifier: Apache-2.0
#include "protocol/geometry/fit_options_codec.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "core/spline/spline_fit_table.hpp"
#include "protocol/message_fields.hpp"

namespace wrc::protocol {
namespace {

// The field of each spline_fit_table() key.
const std::vector<MessageField<spline_fit_options_t>>& fit_fields() {
  using M = spline_fit_options_t;
  static const std::vector<MessageField<M>> fields{
      WRC_MESSAGE_FIELD(M, y_min),        WRC_MESSAGE_FIELD(M, y_max),        WRC_MESSAGE_FIELD(M, roll_max),
      WRC_MESSAGE_FIELD(M, yaw_max),      WRC_MESSAGE_FIELD(M, grading),      WRC_MESSAGE_FIELD(M, sample_step_y),
      WRC_MESSAGE_FIELD(M, roll_samples), WRC_MESSAGE_FIELD(M, yaw_samples),  WRC_MESSAGE_FIELD(M, jump_weight),
      WRC_MESSAGE_FIELD(M, jump_band),    WRC_MESSAGE_FIELD(M, transition),   WRC_MESSAGE_FIELD(M, transition_load),
      WRC_MESSAGE_FIELD(M, flange_angle),
      WRC_MESSAGE_FIELD(M, clearance_cap),
  };
  return fields;
}

}  // namespace

spline_fit_options_t to_message(const SplineFitOptions& o) {
  spline_fit_options_t m;
  to_message_fields(spline_fit_table(), o, fit_fields(), m);
  for (int k = 0; k < 3; ++k) {
    m.intervals[k] = o.intervals[static_cast<size_t>(k)];
    m.degrees[k] = static_cast<int8_t>(o.degrees[static_cast<size_t>(k)]);
  }
  m.knot_placement =
      o.placement == KnotPlacement::kUniform ? spline_fit_options_t::UNIFORM : spline_fit_options_t::GRADED;
  m.num_y_breakpoints = static_cast<int32_t>(o.y_breakpoints.size());
  m.y_breakpoints = o.y_breakpoints;
  return m;
}

SplineFitOptions from_message(const spline_fit_options_t& m) {
  SplineFitOptions o;
  try {
    from_message_fields(spline_fit_table(), m, fit_fields(), o);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("spline_fit_options_t: ") + e.what());
  }
  for (int k = 0; k < 3; ++k) {
    o.intervals[static_cast<size_t>(k)] = m.intervals[k];
    o.degrees[static_cast<size_t>(k)] = m.degrees[k];
  }
  if (m.knot_placement != spline_fit_options_t::UNIFORM && m.knot_placement != spline_fit_options_t::GRADED)
    throw std::invalid_argument("spline_fit_options_t: knot_placement = " + std::to_string(m.knot_placement) +
                                " is neither UNIFORM (0) nor GRADED (1)");
  o.placement = m.knot_placement == spline_fit_options_t::UNIFORM ? KnotPlacement::kUniform : KnotPlacement::kGraded;
  if (m.num_y_breakpoints < 0 || static_cast<size_t>(m.num_y_breakpoints) != m.y_breakpoints.size())
    throw std::invalid_argument("spline_fit_options_t: num_y_breakpoints = " + std::to_string(m.num_y_breakpoints) +
                                " does not match the array");
  o.y_breakpoints = m.y_breakpoints;
  o.validate();  // the triples, the breakpoints and the rules between members
  return o;
}
}  // namespace wrc::protocol
