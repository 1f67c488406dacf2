// SPDX-License-Identifier: Apache-2.0
#include "bus/service/percentile.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace wrc::bus {

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(samples.begin(), samples.end());
  const std::size_t last = samples.size() - 1;
  return samples[std::min(last, static_cast<std::size_t>(p * last + 0.5))];
}

}  // namespace wrc::bus
