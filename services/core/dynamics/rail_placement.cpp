// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/rail_placement.hpp"

#include <cmath>

namespace wrc {

std::array<RailOffset, 2> rail_offsets_at(const IrregularityPoint& p, double cant_base, double speed) {
  const auto slope = [&p](IrregularityChannel c) { return p.slope[static_cast<std::size_t>(c)]; };
  const double ratio = p.cross_level / cant_base;
  const double roll = std::asin(ratio);
  const double roll_rate = speed * slope(IrregularityChannel::kCrossLevel) / (cant_base * std::sqrt(1.0 - ratio * ratio));
  std::array<RailOffset, 2> rails;
  for (int i = 0; i < 2; ++i) {
    const double sign = i == 0 ? 1.0 : -1.0;  // left rail: + half the gauge and cross-level
    RailOffset& r = rails[static_cast<std::size_t>(i)];
    r.lateral = p.alignment + sign * 0.5 * p.gauge;
    r.vertical = p.vertical_level + sign * 0.5 * p.cross_level;
    r.roll = roll;
    r.lateral_rate = speed * (slope(IrregularityChannel::kAlignment) + sign * 0.5 * slope(IrregularityChannel::kGauge));
    r.vertical_rate =
        speed * (slope(IrregularityChannel::kVerticalLevel) + sign * 0.5 * slope(IrregularityChannel::kCrossLevel));
    r.roll_rate = roll_rate;
  }
  return rails;
}

}  // namespace wrc
