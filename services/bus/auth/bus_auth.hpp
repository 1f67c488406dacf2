// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The process's message authentication: one bus key and one sender nonce per process, used by
/// every signed publish (bus/auth/signed_publish.hpp) and every guarded subscription
/// (bus/transport/guarded_subscription.hpp). open_lcm() (bus/service/service_loop.hpp) loads the key, so a
/// process that opens the bus through it needs nothing else.

#include <string>

#include "bus/auth/bus_key.hpp"
#include "bus/auth/message_auth.hpp"

namespace wrc::bus {

/// Makes key the process's bus key, with a fresh random sender nonce (replaces an earlier one;
/// call before any thread publishes).
void install_bus_key(const BusKey& key);
/// Reads the key at bus_key_path(option) and installs it, unless a key is installed already.
/// Throws std::runtime_error from read_bus_key() (missing file, permissions, format).
void load_bus_key(const std::string& option = "");
/// For processes that start services (`wrc launch`, `wrc query`): reads the key at
/// bus_key_path(option), creating it when missing (with a log line `<who>: created bus key FILE
/// ...`), installs it, and sets $WRC_BUS_KEY to its path so that started services use the same
/// file. Returns the path.
std::string prepare_bus_key(const std::string& option, const std::string& who);
/// The installed authentication. Throws std::logic_error when no key is installed (a process
/// must load the key before it touches the bus).
MessageAuth& bus_auth();

}  // namespace wrc::bus
