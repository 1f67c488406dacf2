// SPDX-License-Identifier: Apache-2.0
#include "protocol/contact/contact_lane.hpp"

#include "core/models/contact_model_factory.hpp"

namespace wrc::protocol {

int contact_query_lane(const std::string& model) {
  const ContactModelEntry& entry = contact_model_entry(model);  // throws for an unknown one
  return static_cast<int>(&entry - contact_model_registry().data()) + 1;
}

int contact_reply_lane(const std::string& model) {
  return contact_query_lane(model) + static_cast<int>(contact_model_registry().size());
}

}  // namespace wrc::protocol
