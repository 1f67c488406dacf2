// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/contact_evaluator.hpp"

#include <stdexcept>

namespace wrc {

QueryTimes& QueryTimes::operator+=(const QueryTimes& o) {
  round_trip += o.round_trip;
  send += o.send;
  transfer += o.transfer;
  service_wakeup += o.service_wakeup;
  compute += o.compute;
  reply += o.reply;
  client_wakeup += o.client_wakeup;
  return *this;
}

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
