// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The contact query and its reply in message form and their library counterparts:
/// contact_query_t -> ContactQuery (one per configuration) and back, ContactResult <->
/// contact_result_t, and the checks of a query's fields. Used by wrc-contactd (which answers
/// queries: contactd/query_evaluation.hpp) and by the dynamics' bus client (which sends them).
/// No transport here, so it is used and tested in-process.

#include <string>
#include <vector>

#include "core/model_interface/contact_model.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_result_t.hpp"

namespace wrc::protocol {

/// Largest batch of one query (keeps the reply in one UDP datagram, contact_query_t.lcm).
inline constexpr int kMaxConfigurations = 32;

/// Checks a query before any computation: what the message alone needs (a known formulation, the
/// batch size, as many configurations as it says), then each configuration converted by
/// to_contact_query against the library's rule (core/model_interface/query_validation.hpp), so
/// that the bus accepts what the models accept. Returns an empty string when valid, else one line
/// naming the message field and its value, e.g. "configurations[0].y = nan is not a finite number".
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

/// Whether two library queries share what a bus query carries once for all its configurations:
/// formulation, material and FASTSIM grid (bit for bit).
bool shares_query_fields(const ContactQuery& a, const ContactQuery& b);

/// A bus query for a batch of library queries that share formulation, material and grid
/// (shares_query_fields): every field but header, request id, client, channel, model, instance
/// and geometry key. @throws std::invalid_argument for an empty batch or one whose queries do not
/// share those fields (naming the first that differs).
void to_query_message(const std::vector<ContactQuery>& batch, wrc::contact_query_t& query);

}  // namespace wrc::protocol
