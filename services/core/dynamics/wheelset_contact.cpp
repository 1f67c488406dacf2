// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_contact.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/model_interface/followed_points.hpp"
#include "core/model_interface/query_validation.hpp"
#include "core/models/contact_model_factory.hpp"

namespace wrc {
namespace {

// [-] contact results kept for the states last asked: the step's residual states, its event and
// output state, and a Jacobian's perturbed states fetched with its residual (at most
// kTwoPointRigidUnknowns).
constexpr size_t kCacheSize = 32;

}  // namespace

ContactFormulation formulation_of(const ContactEvaluator& contact) {
  return contact_model_entry(contact.model()).dynamics_formulation;
}

WheelsetContact::WheelsetContact(std::shared_ptr<ContactEvaluator> evaluator, const WheelsetEquations& equations,
                                 bool rails_move)
    : evaluator_(std::move(evaluator)), equations_(equations), rails_move_(rails_move),
      formulation_(evaluator_ ? formulation_of(*evaluator_) : ContactFormulation::kRigid) {}

std::vector<ContactResult> evaluate_counted(ContactEvaluator& evaluator, const std::vector<ContactQuery>& batch,
                                            RunCounters& counters) {
  ++counters.contact_queries;
  counters.contact_configurations += static_cast<long>(batch.size());
  std::vector<ContactResult> results = evaluator.evaluate(batch);
  if (results.size() != batch.size())
    throw std::runtime_error("contact model " + evaluator.model() + " answered " + std::to_string(results.size()) +
                             " configurations for " + std::to_string(batch.size()));
  return results;
}

std::vector<ContactResult> WheelsetContact::evaluate(const std::vector<ContactQuery>& batch) {
  return evaluate_counted(*evaluator_, batch, counters_);
}

size_t WheelsetContact::contact_cache_size() { return kCacheSize; }

std::vector<double> WheelsetContact::placement_key() const {
  std::vector<double> key{equations_.track().curvature};
  if (rails_move_) {
    for (const RailOffset& r : equations_.rails())
      key.insert(key.end(), {r.lateral, r.vertical, r.roll, r.lateral_rate, r.vertical_rate, r.roll_rate});
  }
  return key;
}

std::vector<double> WheelsetContact::key_of(const double* y, const FollowedBranches& branches,
                                            const std::vector<double>& placement) const {
  const bool two_point = branches.any_two_point();
  std::vector<double> key;
  key.reserve(kTwoPointRigidUnknowns + 4 + placement.size());
  for (int k = 0; k < unknowns(); ++k)
    if (enters_contact_query(formulation_, two_point, k)) key.push_back(y[k]);
  key.insert(key.end(), branches.tracked_s.begin(), branches.tracked_s.end());
  key.insert(key.end(), branches.second_s.begin(), branches.second_s.end());
  key.insert(key.end(), placement.begin(), placement.end());
  return key;
}

WheelsetContact::Ahead WheelsetContact::ahead(const double* y, bool follows) const {
  return {std::vector<double>(y, y + unknowns()), equations_.query(formulation_, y, branches_), placement_key(),
          follows};
}

void WheelsetContact::store(std::vector<double> key, ContactResult result, bool ahead) {
  if (cache_.size() >= kCacheSize) cache_.pop_front();
  cache_.push_back({std::move(key), std::move(result), ahead});
  if (ahead) ++counters_.contact_sent_ahead;
}

std::deque<WheelsetContact::CachedContact>::iterator WheelsetContact::find(const std::vector<double>& key) {
  return std::find_if(cache_.begin(), cache_.end(), [&key](const CachedContact& c) {
    return c.key.size() == key.size() && std::memcmp(c.key.data(), key.data(), key.size() * sizeof(double)) == 0;
  });
}

bool WheelsetContact::keep_last(const std::vector<double>& key) {
  const auto found = find(key);
  if (found == cache_.end()) return false;
  if (std::next(found) != cache_.end()) {
    CachedContact kept = std::move(*found);
    cache_.erase(found);
    cache_.push_back(std::move(kept));
  }
  return true;
}

bool WheelsetContact::asked_and_cached(const std::vector<double>& key) {
  if (!keep_last(key)) return false;
  CachedContact& kept = cache_.back();
  if (kept.ahead) ++counters_.contact_ahead_used;
  kept.ahead = false;
  return true;
}

WheelsetContact::Pending WheelsetContact::pending(const std::vector<const double*>& states) {
  if (states.size() > kCacheSize)
    throw std::logic_error("WheelsetContact: " + std::to_string(states.size()) + " states at once, the cache keeps " +
                           std::to_string(kCacheSize));
  Pending p;
  for (const double* y : states) {
    std::vector<double> key = key_of(y);
    // A state asked for now and cached goes to the back, so that the new results cannot push it out.
    if (asked_and_cached(key)) continue;
    p.keys.push_back(std::move(key));
    p.queries.push_back(equations_.query(formulation_, y, branches_));
  }
  return p;
}

void WheelsetContact::deliver(Pending pending, std::vector<ContactResult> results) {
  if (results.size() != pending.queries.size())
    throw std::runtime_error("contact model " + evaluator_->model() + " answered " + std::to_string(results.size()) +
                             " configurations for " + std::to_string(pending.queries.size()));
  for (size_t i = 0; i < results.size(); ++i) store(std::move(pending.keys[i]), std::move(results[i]), false);
}

void WheelsetContact::fetch(const std::vector<const double*>& states) {
  Pending p = pending(states);
  if (p.queries.empty()) return;
  std::vector<ContactResult> results = evaluate(p.queries);
  deliver(std::move(p), std::move(results));
}

void WheelsetContact::fetch_with(const double* y, const std::vector<Ahead>& ahead) {
  if (ahead.size() + 1 > kCacheSize)
    throw std::logic_error("WheelsetContact: " + std::to_string(ahead.size() + 1) + " states at once, the cache keeps " +
                           std::to_string(kCacheSize));
  std::vector<double> base_key = key_of(y);
  const bool base_cached = asked_and_cached(base_key);
  // The branches a following state will be asked with: those follow() gives after y's answer.
  const auto followed_branches = [this](const ContactResult& answer) {
    FollowedBranches b = branches_;
    follow_answered_points(answer, b.tracked_s, b.second_s);
    return b;
  };
  std::vector<ContactQuery> batch;
  std::vector<const Ahead*> sent;           // the ahead states in the batch, in order
  std::vector<std::vector<double>> keys;    // their keys where known before the answer
  if (!base_cached) batch.push_back(equations_.query(formulation_, y, branches_));
  for (const Ahead& a : ahead) {
    // A forecast state the query rules refuse (it may never be asked) is left out, so that it
    // cannot fail the batch.
    if (find_query_violation(a.query)) continue;
    ContactQuery q = a.query;
    std::vector<double> key;
    if (a.follows && base_cached) {
      // y's answer is known: follow it here.
      const ContactResult& answer = find(base_key)->result;
      key = key_of(a.state.data(), followed_branches(answer), a.placement);
      follow_answered_points(answer, q.tracked_s_wheel, q.second_tracked_s_wheel);
    } else if (a.follows) {
      q.follows = 1;  // y is the batch's first configuration
    } else {
      key = key_of(a.state.data(), branches_, a.placement);
    }
    if (!key.empty() && keep_last(key)) continue;
    batch.push_back(q);
    sent.push_back(&a);
    keys.push_back(std::move(key));
  }
  if (batch.empty()) return;
  std::vector<ContactResult> results = evaluate(batch);
  size_t next = 0;
  FollowedBranches after_answer = branches_;
  if (!base_cached) {
    after_answer = followed_branches(results[0]);
    store(std::move(base_key), std::move(results[next++]), false);
  }
  for (size_t i = 0; i < sent.size(); ++i, ++next) {
    std::vector<double> key = keys[i].empty() ? key_of(sent[i]->state.data(), after_answer, sent[i]->placement)
                                              : std::move(keys[i]);
    store(std::move(key), std::move(results[next]), true);
  }
}

const ContactResult& WheelsetContact::at(const double* y, const std::vector<Ahead>& ahead) {
  if (ahead.empty()) {
    fetch({y});
  } else {
    try {
      fetch_with(y, ahead);
    } catch (const ContactConfigurationError&) {
      fetch({y});  // what the states ahead could not have: y alone, as without them
    }
  }
  return find(key_of(y))->result;  // y's result is cached: at most kCacheSize states were fetched
}

std::vector<ContactResult> WheelsetContact::at_each(const std::vector<const double*>& states) {
  fetch(states);
  std::vector<ContactResult> results;
  results.reserve(states.size());
  for (const double* y : states) results.push_back(find(key_of(y))->result);
  return results;
}

void WheelsetContact::set_branches(const FollowedBranches& branches, std::vector<double>& y) {
  const bool now = branches.any_two_point();
  branches_ = branches;
  if (formulation_ == ContactFormulation::kRigid) y.resize(static_cast<size_t>(unknowns()), 0.0);
  for (int i = 0; i < 2 && now; ++i)
    if (!branches_.two_point(i)) y[kUnknownSecondNormalLeft + i] = y[kUnknownSecondMuLeft + i] = 0.0;
  cache_.clear();
}

void WheelsetContact::follow(const ContactResult& c) {
  follow_answered_points(c, branches_.tracked_s, branches_.second_s);
}

void WheelsetContact::set_formulation(ContactFormulation f) {
  formulation_ = f;
  cache_.clear();
}

void WheelsetContact::replace(std::shared_ptr<ContactEvaluator> evaluator, ContactFormulation f,
                              const FollowedBranches& branches) {
  evaluator_ = std::move(evaluator);
  formulation_ = f;
  branches_ = branches;
  cache_.clear();
}

}  // namespace wrc
