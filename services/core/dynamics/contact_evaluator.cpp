// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/contact_evaluator.hpp"

#include <stdexcept>

namespace wrc {

InProcessContact::InProcessContact(std::shared_ptr<const ContactModel> model) : model_(std::move(model)) {
  if (!model_) throw std::invalid_argument("InProcessContact: no contact model");
}

std::vector<ContactResult> InProcessContact::evaluate(const std::vector<ContactQuery>& batch) {
  std::vector<ContactResult> results;
  results.reserve(batch.size());
  for (const ContactQuery& query : batch) results.push_back(model_->evaluate(query));
  return results;
}

}  // namespace wrc
