// SPDX-License-Identifier: Apache-2.0
// The lanes of the contact models (protocol/contact/contact_lane.hpp): each model a query and a
// reply lane of its own, all of them distinct and within the lanes a bus keeps
// (bus/transport/lcm_url.hpp, kMaxLanes); an unknown model named.
#include "protocol/contact/contact_lane.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "bus/transport/lcm_url.hpp"
#include "core/models/contact_model_factory.hpp"

namespace wrc::protocol {
namespace {

TEST(ContactLane, EveryModelHasTwoLanesOfItsOwn) {
  EXPECT_EQ(contact_query_lane("onepoint"), 1);
  EXPECT_EQ(contact_query_lane("spline"), 4);
  EXPECT_EQ(contact_reply_lane("onepoint"), 5);
  EXPECT_EQ(contact_reply_lane("spline"), 8);
  std::set<int> lanes;
  for (const std::string& model : contact_model_names()) {
    for (int lane : {contact_query_lane(model), contact_reply_lane(model)}) {
      EXPECT_TRUE(lanes.insert(lane).second) << model << ": lane " << lane << " taken twice";
      EXPECT_GE(lane, 1) << model;
      EXPECT_LE(lane, bus::kMaxLanes) << model;
    }
  }
  EXPECT_EQ(lanes.size(), 2 * contact_model_names().size());
}

TEST(ContactLane, UnknownModelIsNamed) {
  try {
    contact_query_lane("tram");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'tram'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wrc::protocol
