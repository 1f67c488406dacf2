// SPDX-License-Identifier: Apache-2.0
#pragma once
// The benchmarks' bus key: a fresh key file in a temporary directory of the run, installed in
// this process and handed to the services it starts through $WRC_BUS_KEY (the user's own key is
// neither needed nor touched).
#include <stdlib.h>

#include <stdexcept>
#include <string>

#include "bus/auth/bus_auth.hpp"
#include "bus/auth/bus_key.hpp"

namespace wrc::bench {

inline void use_temporary_bus_key() {
  char dir[] = "/tmp/wrc-bench-key-XXXXXX";
  if (::mkdtemp(dir) == nullptr) throw std::runtime_error("cannot create a directory for the bench's bus key");
  const std::string path = std::string(dir) + "/bus.key";
  bus::install_bus_key(bus::read_or_create_bus_key(path));
  ::setenv("WRC_BUS_KEY", path.c_str(), 1);
}

}  // namespace wrc::bench
