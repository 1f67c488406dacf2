// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A run's output samples gathered into batches (wheelset_states_t on WHEELSET_STATE): a batch goes
/// out when it holds wheelset_states_t::MAX_STATES samples, when its first sample has waited
/// MAX_AGE_MS of wall time, and when told (the run's end, before its summary). A message per
/// sample cost the run 12-35 us each (docs/performance.md, "The cost of a query").

#include <functional>
#include <string>

#include "wrc/wheelset_states_t.hpp"

namespace wrc::dynamics {

class StateBatches {
 public:
  /// Publishes one batch (header stamped by the caller).
  using Publish = std::function<void(wheelset_states_t&)>;
  explicit StateBatches(Publish publish) : publish_(std::move(publish)) {}

  /// Starts the batches of run_id; a batch still held is published first.
  void start(const std::string& run_id);
  /// Adds one sample; now [s] is the monotonic wall time. Publishes the batch first when its first
  /// sample is MAX_AGE_MS old, and after adding when it is full.
  void add(const wheelset_state_t& state, double now);
  /// Publishes the batch when its first sample is MAX_AGE_MS old at now [s] (monotonic).
  void tick(double now);
  /// Publishes what is held (nothing when empty).
  void flush();
  /// Forgets what is held (a run that failed to start).
  void discard();
  /// [-] batches published since construction.
  long published() const { return published_; }

 private:
  Publish publish_;
  wheelset_states_t batch_{};
  double first_added_ = 0.0;  // [s] monotonic time of the batch's first sample
  long published_ = 0;
};

}  // namespace wrc::dynamics
