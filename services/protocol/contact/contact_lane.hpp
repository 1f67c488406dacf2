// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The lanes of the bus (bus/transport/lcm_url.hpp, lane_lcm_url) that carry a contact model's
/// queries and replies, two per model: the model's instances listen on its query lane, the
/// dynamics on its reply lane, and each publishes on the other's through an LCM object that
/// subscribes to nothing (so has no receive socket). A run's query then reaches only the instances
/// of its model and its reply only the dynamics processes asking that model, where on the bus every
/// datagram reaches every process (the sender's own included), each copy delivered within the
/// send call (docs/performance.md, "The cost of a query"). The services answer on the bus as well.

#include <string>

namespace wrc::protocol {

/// [-] the query lane of model: 1 + its place in the model registry (onepoint 1, interp 2,
/// multipoint 3, spline 4). Throws std::invalid_argument naming an unknown model and the known ones.
int contact_query_lane(const std::string& model);

/// [-] the reply lane of model: its query lane + the number of models (onepoint 5 ... spline 8).
int contact_reply_lane(const std::string& model);

}  // namespace wrc::protocol
