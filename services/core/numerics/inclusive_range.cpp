// SPDX-License-Identifier: Apache-2.0
#include "core/numerics/inclusive_range.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/numerics/number_text.hpp"

namespace wrc {

long inclusive_range_count(double from, double to, double step) {
  const auto bad = [&](const char* why) {
    throw std::invalid_argument("range " + shortest_number_text(from) + ":" + shortest_number_text(to) + ":" +
                                shortest_number_text(step) + ": " + why);
  };
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(step)) bad("values must be finite");
  if (!(step > 0.0)) bad("the step must be positive");
  if (to < from) bad("TO is below FROM (FROM:TO:STEP)");
  const double steps = std::floor((to - from) / step + 1e-9);
  if (steps >= 1e15) bad("more values than can be counted");
  return static_cast<long>(steps) + 1;
}

std::vector<double> inclusive_range(double from, double to, double step) {
  const long count = inclusive_range_count(from, to, step);
  std::vector<double> values;
  values.reserve(static_cast<size_t>(count));
  for (long i = 0; i < count; ++i) values.push_back(std::min(to, from + static_cast<double>(i) * step));
  return values;
}

}  // namespace wrc
