// SPDX-License-Identifier: Apache-2.0
#include "core/geometry/track_table.hpp"

namespace wrc {

const std::vector<Parameter<TrackParameters>>& track_parameter_table() {
  using T = TrackParameters;
  static const std::vector<Parameter<T>> table{
      member_parameter<T>({"gauge", nullptr, "m", "track gauge, measured --gauge-depth below the top of rail",
                           ParameterKind::kNumber, closed(0.5, 2.5)}, &T::gauge),
      member_parameter<T>({"gauge_depth", nullptr, "m", "depth below the top of rail where the gauge is measured",
                           ParameterKind::kNumber, closed(0.0, 0.05)}, &T::gauge_depth),
      member_parameter<T>({"flange_back_spacing", "--flange-back", "m", "flange-back spacing", ParameterKind::kNumber,
                           closed(0.4, 2.4)}, &T::flange_back_spacing),
      member_parameter<T>({"taping_line_offset", nullptr, "m",
                           "distance of the taping line from the wheel's inner face", ParameterKind::kNumber,
                           closed(0.0, 0.2)}, &T::taping_line_offset),
      member_parameter<T>({"inclination", nullptr, "rad", "rail inclination: 1:40, 1:20, none, or an angle",
                           ParameterKind::kNumber, closed(-0.2, 0.2), "1:40", &parse_inclination}, &T::inclination),
      member_parameter<T>({"nominal_radius", "--r0", "m", "nominal rolling radius", ParameterKind::kNumber,
                           closed(0.1, 1.5)}, &T::nominal_radius),
  };
  return table;
}

}  // namespace wrc
