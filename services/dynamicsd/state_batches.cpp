// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/state_batches.hpp"

namespace wrc::dynamics {

void StateBatches::start(const std::string& run_id) {
  flush();
  batch_.run_id = run_id;
}

void StateBatches::add(const wheelset_state_t& state, double now) {
  tick(now);
  if (batch_.states.empty()) first_added_ = now;
  batch_.states.push_back(state);
  batch_.num_states = static_cast<std::int32_t>(batch_.states.size());
  if (batch_.num_states >= wheelset_states_t::MAX_STATES) flush();
}

void StateBatches::tick(double now) {
  if (!batch_.states.empty() && now - first_added_ >= 1e-3 * wheelset_states_t::MAX_AGE_MS) flush();
}

void StateBatches::discard() {
  batch_.states.clear();
  batch_.num_states = 0;
}

void StateBatches::flush() {
  if (batch_.states.empty()) return;
  publish_(batch_);
  ++published_;
  batch_.states.clear();
  batch_.num_states = 0;
}

}  // namespace wrc::dynamics
