// SPDX-License-Identifier: Apache-2.0
#include "core/vehicle_dynamics/vehicle_contact.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace wrc {

VehicleContact::VehicleContact(std::shared_ptr<ContactEvaluator> evaluator, const VehicleEquations& equations,
                               bool rails_move)
    : evaluator_(std::move(evaluator)), equations_(equations) {
  if (!evaluator_) throw std::invalid_argument("VehicleContact: no contact evaluator");
  wheelsets_.reserve(equations.wheelset_count());
  for (size_t w = 0; w < equations.wheelset_count(); ++w)
    wheelsets_.emplace_back(evaluator_, equations.wheelset(w), rails_move);
}

void VehicleContact::replace(std::shared_ptr<ContactEvaluator> evaluator, ContactFormulation f,
                             const std::vector<FollowedBranches>& branches) {
  if (!evaluator) throw std::invalid_argument("VehicleContact::replace: no contact evaluator");
  if (!branches.empty() && branches.size() != wheelsets_.size())
    throw std::invalid_argument("VehicleContact::replace: branches of " + std::to_string(branches.size()) +
                                " wheelsets for " + std::to_string(wheelsets_.size()));
  evaluator_ = std::move(evaluator);
  for (size_t w = 0; w < wheelsets_.size(); ++w)
    wheelsets_[w].replace(evaluator_, f, branches.empty() ? FollowedBranches{} : branches[w]);
}

std::vector<FollowedBranches> VehicleContact::branches() const {
  std::vector<FollowedBranches> b;
  for (const WheelsetContact& c : wheelsets_) b.push_back(c.branches());
  return b;
}

std::vector<int> VehicleContact::unknowns() const {
  std::vector<int> n;
  for (const WheelsetContact& c : wheelsets_) n.push_back(c.unknowns());
  return n;
}

void VehicleContact::fetch(const std::vector<std::vector<const double*>>& states) {
  if (states.size() != wheelsets_.size())
    throw std::logic_error("VehicleContact::fetch: states of " + std::to_string(states.size()) + " wheelsets for " +
                           std::to_string(wheelsets_.size()));
  std::vector<WheelsetContact::Pending> pending;
  std::vector<ContactQuery> batch;
  for (size_t w = 0; w < wheelsets_.size(); ++w) {
    pending.push_back(wheelsets_[w].pending(states[w]));
    batch.insert(batch.end(), pending.back().queries.begin(), pending.back().queries.end());
  }
  if (batch.empty()) return;
  std::vector<ContactResult> results = evaluate_counted(*evaluator_, batch, counters_);
  auto next = results.begin();
  for (size_t w = 0; w < wheelsets_.size(); ++w) {
    const auto count = static_cast<std::ptrdiff_t>(pending[w].queries.size());
    std::vector<ContactResult> own(std::make_move_iterator(next), std::make_move_iterator(next + count));
    next += count;
    wheelsets_[w].deliver(std::move(pending[w]), std::move(own));
  }
}

std::vector<WheelsetContactView> VehicleContact::at(const VehicleLayout& layout, const double* y) {
  std::vector<std::vector<const double*>> states(wheelsets_.size());
  for (size_t w = 0; w < wheelsets_.size(); ++w) states[w] = {y + layout.offset[equations_.wheelset_body(w)]};
  fetch(states);
  std::vector<WheelsetContactView> views;
  for (size_t w = 0; w < wheelsets_.size(); ++w) {
    WheelsetContact& c = wheelsets_[w];
    views.push_back({c.formulation(), &c.branches(), &c.at(states[w][0])});
  }
  return views;
}

void VehicleContact::clear_cache() {
  for (WheelsetContact& c : wheelsets_) c.clear_cache();
}

}  // namespace wrc
