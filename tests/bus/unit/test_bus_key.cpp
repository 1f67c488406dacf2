// SPDX-License-Identifier: Apache-2.0
// Every unit test of the bus runs with a bus key installed (a fixed test key: these tests never
// leave the process, memq://), as open_lcm() would install the user's key in a real process.
#include <gtest/gtest.h>

#include "test_bus_key.hpp"

#include "bus/auth/bus_auth.hpp"

namespace wrc::bus::test {

BusKey test_bus_key() {
  BusKey key;
  for (std::size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<std::uint8_t>(i * 7 + 1);
  return key;
}

}  // namespace wrc::bus::test

namespace {

class TestBusKey : public ::testing::Environment {
 public:
  void SetUp() override { wrc::bus::install_bus_key(wrc::bus::test::test_bus_key()); }
};

[[maybe_unused]] ::testing::Environment* const kTestBusKey = ::testing::AddGlobalTestEnvironment(new TestBusKey);

}  // namespace
