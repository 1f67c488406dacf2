// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The contact of a wheelset run as its equations see it: the contact evaluator, the formulation
/// it implies, the branches the run follows on each wheel, and the contact results kept for the
/// states last asked (the residual, event and output functions ask again for the states of the
/// step just taken). It counts the contact queries it sends.

#include <deque>
#include <memory>
#include <vector>

#include "core/dynamics/contact_evaluator.hpp"
#include "core/dynamics/followed_branches.hpp"
#include "core/dynamics/run_counters.hpp"
#include "core/dynamics/wheelset_equations.hpp"

namespace wrc {

/// The formulation the dynamics takes for the evaluator's contact model.
ContactFormulation formulation_of(const ContactEvaluator& contact);

/// One evaluation of batch by evaluator, counted in counters (contact_queries one more,
/// contact_configurations the batch's size): one result per query in order.
/// @throws std::runtime_error when the evaluator answers another number of results.
std::vector<ContactResult> evaluate_counted(ContactEvaluator& evaluator, const std::vector<ContactQuery>& batch,
                                            RunCounters& counters);

class WheelsetContact {
 public:
  /// @param equations give each query the pose, the track and the rails; they must outlive this.
  /// @param rails_move whether the rails move (irregularities): their offsets then enter the
  ///        cache's key.
  WheelsetContact(std::shared_ptr<ContactEvaluator> evaluator, const WheelsetEquations& equations, bool rails_move);

  const std::shared_ptr<ContactEvaluator>& evaluator() const { return evaluator_; }
  ContactFormulation formulation() const { return formulation_; }
  const FollowedBranches& branches() const { return branches_; }
  /// Unknowns of the current formulation and branches (unknown_count()).
  int unknowns() const { return unknown_count(formulation_, branches_.any_two_point()); }

  /// A state whose contact travels with another's (at(y, ahead)): its query, prepared under the
  /// track placement of its own time (ahead()), the placement part of its cache key, and whether
  /// it follows the points answered for the state it travels with (a state the caller will ask
  /// after follow()ing that answer, e.g. the next step's predictor after an accepted step).
  struct Ahead {
    std::vector<double> state;
    ContactQuery query;
    std::vector<double> placement;
    bool follows = false;
  };
  /// The Ahead of the state y under the equations' current placement.
  Ahead ahead(const double* y, bool follows) const;

  /// The contact at the state y, usually from the cache; valid until the next call.
  const ContactResult& at(const double* y) { return at(y, {}); }
  /// The contact at the state y as at(y), and at each state of ahead whose contact is not cached
  /// yet, all in one evaluation (one round trip), every result cached under the key the state will
  /// have when it is asked (for one that follows: with the branches follow() will give). Should
  /// that evaluation be refused (ContactConfigurationError), y is evaluated alone, as without
  /// ahead. At most contact_cache_size() states in all.
  const ContactResult& at(const double* y, const std::vector<Ahead>& ahead);
  /// The contact at each state, from the cache where it is there, the rest in one evaluation
  /// (cached too). At most contact_cache_size() states.
  std::vector<ContactResult> at_each(const std::vector<const double*>& states);
  /// How many states' contact the cache keeps [-].
  static size_t contact_cache_size();
  /// The queries of the states whose contact is not cached yet, with the keys they will be cached
  /// under: for a caller that evaluates several wheelsets' queries in one batch (a vehicle) and
  /// hands each its results by deliver(). A state asked for now and cached goes to the back of the
  /// cache (so that delivered results cannot push it out). At most contact_cache_size() states.
  struct Pending {
    std::vector<std::vector<double>> keys;
    std::vector<ContactQuery> queries;
  };
  Pending pending(const std::vector<const double*>& states);
  /// Caches results, one per query of pending in order (evaluated elsewhere, counted there).
  /// @throws std::runtime_error when their number differs from the queries'.
  void deliver(Pending pending, std::vector<ContactResult> results);
  /// One evaluation of a batch, one result per query in order (not cached).
  /// @throws std::runtime_error when the evaluator answers another number of results.
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch);
  void clear_cache() { cache_.clear(); }

  /// Follows other branches: the state resized to their layout (rigid), the contact cache cleared.
  void set_branches(const FollowedBranches& branches, std::vector<double>& y);
  /// Follows the points of c (the contact at an accepted step) on the branches it is on.
  void follow(const ContactResult& c);
  /// The formulation alone (the start takes both formulations from rigid contact); the cache is
  /// cleared.
  void set_formulation(ContactFormulation f);
  /// Another evaluator, formulation and branches (a model swap, or its undoing); the cache is
  /// cleared.
  void replace(std::shared_ptr<ContactEvaluator> evaluator, ContactFormulation f, const FollowedBranches& branches);

  /// contact_queries, contact_configurations, contact_sent_ahead and contact_ahead_used so far;
  /// every other counter 0.
  const RunCounters& counters() const { return counters_; }

 private:
  struct CachedContact {
    std::vector<double> key;
    ContactResult result;
    bool ahead = false;  ///< sent before it was asked for, not asked for since
  };
  /// What the contact at y depends on besides the evaluator: the unknowns that enter the query,
  /// the followed branches, and the placement (placement_key()).
  std::vector<double> key_of(const double* y, const FollowedBranches& branches,
                             const std::vector<double>& placement) const;
  std::vector<double> key_of(const double* y) const { return key_of(y, branches_, placement_key()); }
  /// The placement part of a key: the track's curvature (it enters the query's yaw rate and
  /// speed) and (irregularities) the rails' offsets and rates.
  std::vector<double> placement_key() const;
  /// Caches result under key, pushing out the oldest entry when full; ahead: sent before it was
  /// asked for (counted in contact_sent_ahead).
  void store(std::vector<double> key, ContactResult result, bool ahead);
  /// The cached entry of key, or cache_.end().
  std::deque<CachedContact>::iterator find(const std::vector<double>& key);
  /// Moves the cached result of key to the back of the cache (the last to be pushed out);
  /// false when key is not cached.
  bool keep_last(const std::vector<double>& key);
  /// keep_last() for a state asked for now: one sent ahead counts in contact_ahead_used.
  bool asked_and_cached(const std::vector<double>& key);
  /// Evaluates the states whose contact is not cached, in one batch, and caches the results.
  void fetch(const std::vector<const double*>& states);
  /// at(y, ahead)'s evaluation; throws what the evaluator throws.
  void fetch_with(const double* y, const std::vector<Ahead>& ahead);
  std::shared_ptr<ContactEvaluator> evaluator_;
  const WheelsetEquations& equations_;
  bool rails_move_;
  ContactFormulation formulation_;
  FollowedBranches branches_;
  std::deque<CachedContact> cache_;
  RunCounters counters_;
};

}  // namespace wrc
