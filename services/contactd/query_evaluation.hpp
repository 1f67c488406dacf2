// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// What wrc-contactd does with a query: every configuration evaluated by the model, every failure
/// turned into a status and a message (the messages' codec: protocol/contact/contact_query_codec.hpp).

#include "core/model_interface/contact_model.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::contactd {

/// Evaluates every configuration of a validated query with model and fills reply.status,
/// reply.message and reply.results (one per configuration, in query order). Per configuration:
/// NoContactError -> NO_CONTACT, OutsideModelError -> OUTSIDE_MODEL, ContactConfigurationError -> IMPOSSIBLE_CONFIGURATION,
/// std::invalid_argument -> BAD_REQUEST,
/// any other exception -> INTERNAL_ERROR; such a configuration gets no patches and zero
/// resultants. The overall status is the worst one (protocol::contact_status_severity: OK < NO_CONTACT <
/// OUTSIDE_MODEL < IMPOSSIBLE_CONFIGURATION < BAD_REQUEST < INTERNAL_ERROR) and the message that of the first configuration with that status,
/// prefixed "configuration <i> (y=..., roll=..., yaw=...): ". Never throws for a model failure.
void evaluate_query(const ContactModel& model, const wrc::contact_query_t& query, wrc::contact_reply_t& reply);

}  // namespace wrc::contactd
