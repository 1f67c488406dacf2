// SPDX-License-Identifier: Apache-2.0
#pragma once
// The bus key every unit test of the bus runs with (installed before the first test).
#include "bus/auth/bus_key.hpp"

namespace wrc::bus::test {

/// The fixed key of the unit tests.
BusKey test_bus_key();

}  // namespace wrc::bus::test
