// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Which lane of the bus (bus/transport/lcm_url.hpp, lane_lcm_url) carries a contact model's
/// queries and replies: each model its own, so that a run's contact traffic wakes only the
/// dynamics and the instances of its model, not every process of the bus
/// (docs/performance.md, "The cost of a query"). The services answer on the bus as well.

#include <string>

namespace wrc::protocol {

/// [-] the lane of model (1 + its place in the model registry: onepoint 1, interp 2,
/// multipoint 3, spline 4). Throws std::invalid_argument naming an unknown model and the known ones.
int contact_lane(const std::string& model);

}  // namespace wrc::protocol
