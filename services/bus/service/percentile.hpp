// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Percentiles of timing samples (benchmarks, service logs).

#include <vector>

namespace wrc::bus {

/// The sample at rank round(p (n - 1)) of the sorted samples (p in [0, 1]; 0.5: the median), in the
/// samples' unit; NaN when there are none.
double percentile(std::vector<double> samples, double p);

}  // namespace wrc::bus
