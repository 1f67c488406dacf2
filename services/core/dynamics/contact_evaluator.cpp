// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/contact_evaluator.hpp"

#include "core/model_interface/followed_points.hpp"

#include <stdexcept>

namespace wrc {

InProcessContact::InProcessContact(std::shared_ptr<const ContactModel> model) : model_(std::move(model)) {
  if (!model_) throw std::invalid_argument("InProcessContact: no contact model");
}

std::vector<ContactResult> InProcessContact::evaluate(const std::vector<ContactQuery>& batch) {
  std::vector<ContactResult> results;
  results.reserve(batch.size());
  std::vector<const ContactResult*> answered;
  for (const ContactQuery& query : batch) {
    ContactQuery followed = query;
    apply_follows(answered, static_cast<int>(results.size()), followed);
    results.push_back(model_->evaluate(followed));
    answered.assign(results.size(), nullptr);
    for (size_t k = 0; k < results.size(); ++k) answered[k] = &results[k];
  }
  return results;
}

}  // namespace wrc
