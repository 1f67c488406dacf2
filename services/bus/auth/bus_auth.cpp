// SPDX-License-Identifier: Apache-2.0
#include "bus/auth/bus_auth.hpp"

#include <cstdlib>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace wrc::bus {

namespace {
std::unique_ptr<MessageAuth>& installed() {
  static std::unique_ptr<MessageAuth> auth;
  return auth;
}
}  // namespace

void install_bus_key(const BusKey& key) {
  installed() = std::make_unique<MessageAuth>(key, MessageAuth::random_nonce());
}

void load_bus_key(const std::string& option) {
  if (!installed()) install_bus_key(read_bus_key(bus_key_path(option)));
}

std::string prepare_bus_key(const std::string& option, const std::string& who) {
  const std::string path = bus_key_path(option);
  bool created = false;
  const BusKey key = read_or_create_bus_key(path, &created);
  if (created) {
    std::cerr << who << ": created bus key " << path
              << " (mode 0600; copy this file to every other machine of this bus)\n";
  }
  install_bus_key(key);
  ::setenv("WRC_BUS_KEY", path.c_str(), 1);
  return path;
}

MessageAuth& bus_auth() {
  if (!installed()) throw std::logic_error("no bus key loaded: call load_bus_key() (or open_lcm()) first");
  return *installed();
}

}  // namespace wrc::bus
