// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A test helper: a WheelsetSimulation run to its end, every output kept.

#include <gtest/gtest.h>

#include <vector>

#include "core/dynamics/wheelset_simulation.hpp"

namespace wrc::test {

/// Runs sim to its end and returns every output snapshot; expects the run to finish.
inline std::vector<WheelsetSnapshot> run_to_end(WheelsetSimulation& sim) {
  std::vector<WheelsetSnapshot> out;
  sim.on_output([&](const WheelsetSnapshot& s) { out.push_back(s); });
  sim.run();
  EXPECT_EQ(sim.state(), RunState::kFinished) << sim.message();
  return out;
}

}  // namespace wrc::test
