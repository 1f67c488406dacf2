// SPDX-License-Identifier: Apache-2.0
// Latency window: mean, 95th percentile and maximum over the most recent samples only.
#include <gtest/gtest.h>

#include <vector>

#include "bus/service/percentile.hpp"
#include "bus/service/service_load.hpp"

namespace {
using wrc::bus::LatencyWindow;
using wrc::bus::ServiceLoad;

// 1..100 ms: mean 50.5 ms, p95 95 ms, max 100 ms.
TEST(LatencyWindow, Statistics) {
  LatencyWindow window(1000);
  for (int i = 1; i <= 100; ++i) window.add(i * 1e-3);
  ServiceLoad load;
  window.summarise(load);
  EXPECT_NEAR(load.latency_mean, 50.5e-3, 1e-12);
  EXPECT_NEAR(load.latency_p95, 95e-3, 1e-12);
  EXPECT_NEAR(load.latency_max, 100e-3, 1e-12);
}

// The window's p95 is bus::percentile(samples, 0.95), the one p95 rule (rank round(0.95 (n - 1))).
// With 13 samples 1..13 ms that is rank round(11.4) = 11, i.e. 12 ms; a nearest-rank rule
// (ceil(0.95 n) - 1 = 12) would give 13 ms, so this case tells the two apart.
TEST(LatencyWindow, P95IsTheSharedPercentile) {
  LatencyWindow window(1000);
  std::vector<double> samples;
  for (int i = 13; i >= 1; --i) {  // added in descending order: the window must sort
    window.add(i * 1e-3);
    samples.push_back(i * 1e-3);
  }
  ServiceLoad load;
  window.summarise(load);
  EXPECT_DOUBLE_EQ(load.latency_p95, wrc::bus::percentile(samples, 0.95));
  EXPECT_NEAR(load.latency_p95, 12e-3, 1e-15);
  EXPECT_NEAR(load.latency_max, 13e-3, 1e-15);
}

// Only the last `capacity` samples count.
TEST(LatencyWindow, ForgetsOldSamples) {
  LatencyWindow window(10);
  for (int i = 0; i < 10; ++i) window.add(1.0);
  for (int i = 0; i < 10; ++i) window.add(2.0);
  ServiceLoad load;
  window.summarise(load);
  EXPECT_EQ(window.size(), 10u);
  EXPECT_DOUBLE_EQ(load.latency_mean, 2.0);
}
}  // namespace
