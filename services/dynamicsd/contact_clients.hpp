// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The dynamics' contact request clients, one per contact model, each on its model's lanes of the
/// bus (protocol/contact/contact_lane.hpp): queries on the query lane, replies on the reply lane,
/// so that a run's queries wake only the instances of its model and its replies only the
/// dynamics processes asking that model. The replies are read from a lane socket in the
/// caller's thread (bus/transport/lane_socket.hpp: no LCM receive thread between the reply and
/// the integration). While a client waits it reads the bus too (heartbeats, commands, swaps).
/// On a bus without lanes (memq, file, tcpq URLs) every model shares one client on the bus
/// itself.

#include <lcm/lcm-cpp.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bus/transport/channels.hpp"
#include "bus/transport/lane_socket.hpp"
#include "bus/transport/request_client.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::dynamics {

using ContactClient = bus::RequestClient<contact_query_t, contact_reply_t>;

class ContactClients {
 public:
  /// bus: the process's LCM object, opened at bus_url (as given to open_lcm; empty = the default).
  /// Opens the lanes of every model. Throws std::runtime_error when one cannot be opened.
  ContactClients(lcm::LCM& bus, std::string bus_url, bus::ChannelNames names, std::string sender);
  ContactClients(const ContactClients&) = delete;
  ContactClients& operator=(const ContactClients&) = delete;

  /// The client for model's queries. Throws std::invalid_argument for an unknown model.
  ContactClient& client(const std::string& model);
  /// The reply lanes' sockets, for the service loop to read while no query waits (what anyone
  /// sends there is read, checked and counted, never left to fill the socket).
  std::vector<bus::LaneSocket*> reply_lanes() const;

 private:
  struct Lane {
    std::unique_ptr<lcm::LCM> queries;  // publishes only: no receive socket
    std::unique_ptr<bus::LaneSocket> replies;
    std::unique_ptr<ContactClient> client;
  };
  std::unique_ptr<ContactClient> make_client(bus::Inbox on) const;

  lcm::LCM& bus_;
  std::string bus_url_;  // effective URL of the bus
  bus::ChannelNames names_;
  std::string sender_;
  std::unique_ptr<ContactClient> on_bus_;  // without lanes
  std::map<std::string, Lane> lanes_;
};

}  // namespace wrc::dynamics
