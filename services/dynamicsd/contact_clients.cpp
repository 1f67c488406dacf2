// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/contact_clients.hpp"

#include "bus/service/service_loop.hpp"
#include "bus/transport/lcm_url.hpp"
#include "core/models/contact_model_factory.hpp"
#include "protocol/contact/contact_lane.hpp"

namespace wrc::dynamics {

ContactClients::ContactClients(lcm::LCM& bus, std::string bus_url, bus::ChannelNames names, std::string sender)
    : bus_(bus), bus_url_(bus::effective_lcm_url(bus_url)), names_(std::move(names)), sender_(std::move(sender)) {
  for (const std::string& model : contact_model_names()) {
    const std::string url = bus::lane_lcm_url(bus_url_, protocol::contact_reply_lane(model));
    if (url.empty()) return;  // no lanes on this bus
    Lane lane;
    lane.replies = std::make_unique<bus::LaneSocket>(url);
    lane.queries = bus::open_lcm(bus::lane_lcm_url(bus_url_, protocol::contact_query_lane(model)));
    lane.client = make_client(*lane.replies);
    lane.client->publish_on(*lane.queries);
    lane.client->also_dispatch(bus_);
    lanes_.emplace(model, std::move(lane));
  }
}

std::vector<bus::LaneSocket*> ContactClients::reply_lanes() const {
  std::vector<bus::LaneSocket*> out;
  for (const auto& [model, lane] : lanes_) out.push_back(lane.replies.get());
  return out;
}

std::unique_ptr<ContactClient> ContactClients::make_client(bus::Inbox on) const {
  // The request channel is set per query (BusContact); this one is a placeholder.
  return std::make_unique<ContactClient>(on, names_.name(bus::channel::kContactQuery, "onepoint"),
                                         names_.name(bus::channel::kContactReply, bus::make_client_id("wrc-dynamicsd")),
                                         sender_);
}

ContactClient& ContactClients::client(const std::string& model) {
  protocol::contact_query_lane(model);  // throws for an unknown model
  const auto found = lanes_.find(model);
  if (found != lanes_.end()) return *found->second.client;
  if (!on_bus_) on_bus_ = make_client(bus_);
  return *on_bus_;
}

}  // namespace wrc::dynamics
