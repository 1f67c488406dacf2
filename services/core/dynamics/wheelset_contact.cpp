// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/wheelset_contact.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

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

std::vector<ContactResult> WheelsetContact::evaluate(const std::vector<ContactQuery>& batch) {
  ++counters_.contact_queries;
  counters_.contact_configurations += static_cast<long>(batch.size());
  std::vector<ContactResult> results = evaluator_->evaluate(batch);
  if (results.size() != batch.size())
    throw std::runtime_error("contact model " + evaluator_->model() + " answered " + std::to_string(results.size()) +
                             " configurations for " + std::to_string(batch.size()));
  return results;
}

size_t WheelsetContact::contact_cache_size() { return kCacheSize; }

std::vector<double> WheelsetContact::key_of(const double* y) const {
  const bool two_point = branches_.any_two_point();
  std::vector<double> key;
  key.reserve(kTwoPointRigidUnknowns + 4);
  for (int k = 0; k < unknowns(); ++k)
    if (enters_contact_query(formulation_, two_point, k)) key.push_back(y[k]);
  key.insert(key.end(), branches_.tracked_s.begin(), branches_.tracked_s.end());
  key.insert(key.end(), branches_.second_s.begin(), branches_.second_s.end());
  // The track's turning rate enters the query's yaw rate and speed (WheelsetEquations::query).
  key.push_back(equations_.track().curvature);
  // The rails' offsets and rates enter the query (irregularities).
  if (rails_move_) {
    for (const RailOffset& r : equations_.rails())
      key.insert(key.end(), {r.lateral, r.vertical, r.roll, r.lateral_rate, r.vertical_rate, r.roll_rate});
  }
  return key;
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

void WheelsetContact::fetch(const std::vector<const double*>& states) {
  if (states.size() > kCacheSize)
    throw std::logic_error("WheelsetContact: " + std::to_string(states.size()) + " states at once, the cache keeps " +
                           std::to_string(kCacheSize));
  std::vector<std::vector<double>> keys;
  std::vector<ContactQuery> batch;
  for (const double* y : states) {
    std::vector<double> key = key_of(y);
    // A state asked for now and cached goes to the back, so that the new results cannot push it out.
    if (keep_last(key)) continue;
    keys.push_back(std::move(key));
    batch.push_back(equations_.query(formulation_, y, branches_));
  }
  if (batch.empty()) return;
  std::vector<ContactResult> results = evaluate(batch);
  for (size_t i = 0; i < results.size(); ++i) {
    if (cache_.size() >= kCacheSize) cache_.pop_front();
    cache_.push_back({std::move(keys[i]), std::move(results[i])});
  }
}

const ContactResult& WheelsetContact::at(const double* y, const std::vector<const double*>& also) {
  std::vector<const double*> states{y};
  states.insert(states.end(), also.begin(), also.end());
  fetch(states);
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
  for (int i = 0; i < 2; ++i) {
    const size_t w = static_cast<size_t>(i);
    branches_.tracked_s[w] = c.wheels[w].s_wheel;
    if (branches_.two_point(i)) branches_.second_s[w] = c.second_wheels[w]->s_wheel;
  }
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
