// SPDX-License-Identifier: Apache-2.0
// percentile(): the sample at rank round(p (n - 1)) of the sorted samples, whatever their order.
#include <gtest/gtest.h>

#include <cmath>

#include "bus/service/percentile.hpp"

namespace {

TEST(Percentile, RankOfSortedSamples) {
  const std::vector<double> samples = {5.0, 1.0, 4.0, 2.0, 3.0};  // unsorted on purpose
  EXPECT_EQ(wrc::bus::percentile(samples, 0.0), 1.0);
  EXPECT_EQ(wrc::bus::percentile(samples, 0.5), 3.0);   // rank 2 of 0..4
  EXPECT_EQ(wrc::bus::percentile(samples, 0.99), 5.0);  // rank round(3.96) = 4
  EXPECT_EQ(wrc::bus::percentile(samples, 1.0), 5.0);
  EXPECT_EQ(wrc::bus::percentile({1.0, 2.0, 3.0, 4.0}, 0.5), 3.0);  // rank round(1.5) = 2
  EXPECT_EQ(wrc::bus::percentile({7.0}, 0.5), 7.0);
  EXPECT_TRUE(std::isnan(wrc::bus::percentile({}, 0.5)));
}

}  // namespace
