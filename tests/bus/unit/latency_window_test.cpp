// Latency window: mean, 95th percentile and maximum over the most recent samples only.
#include <gtest/gtest.h>

#include "bus/service_load.hpp"

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
