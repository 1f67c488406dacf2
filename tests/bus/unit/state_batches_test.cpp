// SPDX-License-Identifier: Apache-2.0
// A run's output samples in batches (dynamicsd/state_batches.hpp): every sample once and in order,
// a batch never above wheelset_states_t::MAX_STATES, a batch out when its first sample is
// MAX_AGE_MS old however few it holds, and what is held out when told (the run's end).
#include "dynamicsd/state_batches.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace wrc::dynamics {
namespace {

wheelset_state_t sample(double t) {
  wheelset_state_t s{};
  s.run_id = "r";
  s.t = t;
  return s;
}

TEST(StateBatches, EverySampleOnceInOrderInFullBatches) {
  std::vector<wheelset_states_t> out;
  StateBatches batches([&](wheelset_states_t& b) { out.push_back(b); });
  batches.start("r");
  const int samples = 2001;  // the benchmark's 2 s at 1 ms, both ends
  for (int k = 0; k < samples; ++k) batches.add(sample(1e-3 * k), 0.0);  // no wall time passes
  batches.flush();
  const int full = samples / wheelset_states_t::MAX_STATES;
  ASSERT_EQ(out.size(), static_cast<std::size_t>(full + 1));
  int next = 0;
  for (const wheelset_states_t& b : out) {
    EXPECT_EQ(b.run_id, "r");
    EXPECT_EQ(b.num_states, static_cast<std::int32_t>(b.states.size()));
    EXPECT_GE(b.num_states, 1);
    EXPECT_LE(b.num_states, wheelset_states_t::MAX_STATES);
    for (const wheelset_state_t& s : b.states) EXPECT_EQ(s.t, 1e-3 * next++);
  }
  EXPECT_EQ(next, samples);
  EXPECT_EQ(out.back().num_states, samples - full * wheelset_states_t::MAX_STATES);
  EXPECT_EQ(batches.published(), full + 1);
  batches.flush();  // nothing held: nothing sent
  EXPECT_EQ(out.size(), static_cast<std::size_t>(full + 1));
}

TEST(StateBatches, ABatchGoesOutWhenItsFirstSampleIsMaxAgeOld) {
  std::vector<wheelset_states_t> out;
  StateBatches batches([&](wheelset_states_t& b) { out.push_back(b); });
  batches.start("r");
  const double age = 1e-3 * wheelset_states_t::MAX_AGE_MS;
  batches.add(sample(0.0), 10.0);
  batches.add(sample(0.1), 10.0 + 0.5 * age);
  batches.tick(10.0 + 0.99 * age);
  EXPECT_TRUE(out.empty());
  batches.tick(10.0 + age);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].num_states, 2);
  batches.tick(100.0);  // nothing held
  EXPECT_EQ(out.size(), 1u);
  // The next batch's age counts from its own first sample.
  batches.add(sample(0.2), 20.0);
  batches.tick(20.0 + 0.5 * age);
  EXPECT_EQ(out.size(), 1u);
}

TEST(StateBatches, ANewRunSendsWhatTheLastOneLeftFirst) {
  std::vector<wheelset_states_t> out;
  StateBatches batches([&](wheelset_states_t& b) { out.push_back(b); });
  batches.start("first");
  batches.add(sample(0.0), 0.0);
  batches.start("second");
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].run_id, "first");
  batches.add(sample(0.0), 0.0);
  batches.flush();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].run_id, "second");
}

}  // namespace
}  // namespace wrc::dynamics
