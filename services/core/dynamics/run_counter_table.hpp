// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The counters of a run, declared once: per member of RunCounters its name (the summary's and,
/// where the message kept an older one, mapped in protocol/run/run_output_codec.cpp), unit,
/// description and how two stretches of a run combine. The integrator_stats_t codec, the run
/// summary's counters and RunCounters::operator+= are generated from it.

#include <vector>

#include "core/dynamics/run_counters.hpp"
#include "core/numerics/parameter_table.hpp"

namespace wrc {

/// How a counter of a later stretch of a run combines with the earlier ones.
enum class CounterSum {
  kSum,   ///< added
  kMax,   ///< the larger one
  kKept,  ///< the earlier one stays (a value of the last step, set by whoever reads IDA)
};

/// One counter: its name, unit, description, kind (whole number or not) and accessors.
struct RunCounter : Parameter<RunCounters> {
  CounterSum sum = CounterSum::kSum;
};

/// Every counter, in RunCounters' order.
const std::vector<RunCounter>& run_counter_table();

}  // namespace wrc
