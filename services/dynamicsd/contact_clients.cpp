// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/contact_clients.hpp"

#include "bus/service/service_loop.hpp"
#include "bus/transport/lcm_url.hpp"
#include "protocol/contact/contact_lane.hpp"

namespace wrc::dynamics {

ContactClients::ContactClients(lcm::LCM& bus, std::string bus_url, bus::ChannelNames names, std::string sender)
    : bus_(bus), bus_url_(bus::effective_lcm_url(bus_url)), names_(std::move(names)), sender_(std::move(sender)) {}

std::unique_ptr<ContactClient> ContactClients::make_client(lcm::LCM& on) const {
  // The request channel is set per query (BusContact); this one is a placeholder.
  return std::make_unique<ContactClient>(on, names_.name(bus::channel::kContactQuery, "onepoint"),
                                         names_.name(bus::channel::kContactReply, bus::make_client_id("wrc-dynamicsd")),
                                         sender_);
}

ContactClient& ContactClients::client(const std::string& model) {
  const std::string url = bus::lane_lcm_url(bus_url_, protocol::contact_reply_lane(model));
  if (url.empty()) {
    if (!on_bus_) on_bus_ = make_client(bus_);
    return *on_bus_;
  }
  auto found = lanes_.find(model);
  if (found == lanes_.end()) {
    Lane lane;
    lane.replies = bus::open_lcm(url);
    lane.queries = bus::open_lcm(bus::lane_lcm_url(bus_url_, protocol::contact_query_lane(model)));
    lane.client = make_client(*lane.replies);
    lane.client->publish_on(*lane.queries);
    lane.client->also_dispatch(bus_);
    found = lanes_.emplace(model, std::move(lane)).first;
  }
  return *found->second.client;
}

}  // namespace wrc::dynamics
