// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The contact of a vehicle's wheelsets: one WheelsetContact per wheelset (its formulation,
/// branches and cache), all answered by one contact evaluator, every wheelset's uncached states in
/// one batch (a four-axle vehicle costs one round trip per evaluation, not four).

#include <memory>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_contact.hpp"
#include "core/vehicle_dynamics/vehicle_equations.hpp"

namespace wrc {

class VehicleContact {
 public:
  /// @param equations give each wheelset's query its pose, track and rails; they must outlive this.
  /// @throws std::invalid_argument for a null evaluator.
  VehicleContact(std::shared_ptr<ContactEvaluator> evaluator, const VehicleEquations& equations, bool rails_move);

  const std::shared_ptr<ContactEvaluator>& evaluator() const { return evaluator_; }
  size_t size() const { return wheelsets_.size(); }
  WheelsetContact& wheelset(size_t w) { return wheelsets_[w]; }
  const WheelsetContact& wheelset(size_t w) const { return wheelsets_[w]; }
  /// Each wheelset's unknown_count() [-], for VehicleEquations::layout_of().
  std::vector<int> unknowns() const;

  /// Fetches the contact of each wheelset w at the states states[w] (pointers to its own unknowns)
  /// that are not cached yet, all in one evaluation, and caches them; afterwards each wheelset's
  /// at() finds them.
  void fetch(const std::vector<std::vector<const double*>>& states);
  /// Each wheelset's contact at the state y of the whole vehicle (fetched in one evaluation where
  /// not cached), valid until the next call.
  std::vector<WheelsetContactView> at(const VehicleLayout& layout, const double* y);

  void clear_cache();
  /// Another evaluator for every wheelset (a model swap, or its undoing), each in formulation f on
  /// the branches of branches (one per wheelset; empty: none followed); the caches cleared.
  /// @throws std::invalid_argument for a null evaluator or branches of another count.
  void replace(std::shared_ptr<ContactEvaluator> evaluator, ContactFormulation f,
               const std::vector<FollowedBranches>& branches = {});
  /// Each wheelset's followed branches.
  std::vector<FollowedBranches> branches() const;
  /// contact_queries (batches) and contact_configurations so far; every other counter 0.
  const RunCounters& counters() const { return counters_; }

 private:
  std::shared_ptr<ContactEvaluator> evaluator_;
  const VehicleEquations& equations_;
  std::vector<WheelsetContact> wheelsets_;
  RunCounters counters_;
};

}  // namespace wrc
