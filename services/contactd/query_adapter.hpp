#pragma once
/// @file
/// The thin adapter between the bus messages and the contact model library:
/// contact_query_t -> ContactQuery (one per configuration), ContactModel::evaluate, and
/// ContactResult -> contact_result_t, with every failure turned into a status and a message.
/// No LCM transport here, so it is used and tested in-process.

#include <string>
#include <vector>

#include "core/models/contact_model.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"
#include "wrc/contact_result_t.hpp"

namespace wrc::contactd {

/// Largest batch of one query (keeps the reply in one UDP datagram, contact_query_t.lcm).
inline constexpr int kMaxConfigurations = 32;

/// Checks the fields of a query before any computation: formulation, material, FASTSIM grid,
/// speed, batch size and every configuration field (finite, in a physical range). Returns an empty
/// string when valid, else one line naming the field and its value, e.g.
/// "configurations[0].y = nan is not a finite number".
std::string validate_query(const wrc::contact_query_t& query);

/// The library query for configuration `index` of a (validated) bus query. z is the height of
/// the wheelset centre above the top-of-rail plane (wheelset_configuration_t.lcm).
ContactQuery to_contact_query(const wrc::contact_query_t& query, int index);

/// Copies a model result into its message form (num_patches = patches.size(), status OK).
void to_result_message(const ContactResult& result, wrc::contact_result_t& message);

/// The reverse of to_result_message, for clients (the dynamics): patches (curvatures are not on
/// the bus and stay 0), wheels, resultants.
ContactResult from_result_message(const wrc::contact_result_t& message);

/// The message form of one configuration of a library query (the reverse of to_contact_query).
void to_configuration_message(const ContactQuery& query, wrc::wheelset_configuration_t& configuration);

/// A bus query for a batch of library queries that share formulation, material, grid and speed
/// (those of the first): every field but header, request id, client, channel, model, instance
/// and geometry key. @throws std::invalid_argument for an empty batch.
void to_query_message(const std::vector<ContactQuery>& batch, wrc::contact_query_t& query);

/// Evaluates every configuration of a validated query with model and fills reply.status,
/// reply.message and reply.results (one per configuration, in query order). Per configuration:
/// NoContactError -> NO_CONTACT, OutsideModelError -> OUTSIDE_MODEL, ContactConfigurationError -> IMPOSSIBLE_CONFIGURATION,
/// std::invalid_argument -> BAD_REQUEST,
/// any other exception -> INTERNAL_ERROR; such a configuration gets no patches and zero
/// resultants. The overall status is the worst one (bus::contact_status_severity: OK < NO_CONTACT <
/// OUTSIDE_MODEL < IMPOSSIBLE_CONFIGURATION < BAD_REQUEST < INTERNAL_ERROR) and the message that of the first configuration with that status,
/// prefixed "configuration <i> (y=..., roll=..., yaw=...): ". Never throws for a model failure.
void evaluate_query(const ContactModel& model, const wrc::contact_query_t& query, wrc::contact_reply_t& reply);

}  // namespace wrc::contactd
