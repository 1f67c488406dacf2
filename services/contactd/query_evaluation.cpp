// SPDX-License-Identifier: Apache-2.0
#include "contactd/query_evaluation.hpp"

#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model_interface/followed_points.hpp"
#include "core/model_interface/no_contact_error.hpp"
#include "core/numerics/number_text.hpp"
#include "protocol/contact/contact_query_codec.hpp"
#include "protocol/contact/contact_status.hpp"

namespace wrc::contactd {
namespace {

std::string configuration_label(const wrc::wheelset_configuration_t& c, int i) {
  return "configuration " + std::to_string(i) + " (y=" + number_text(c.y) + ", roll=" + number_text(c.roll) +
         ", yaw=" + number_text(c.yaw) + "): ";
}

}  // namespace

void evaluate_query(const ContactModel& model, const wrc::contact_query_t& query, wrc::contact_reply_t& reply) {
  reply.status = wrc::contact_reply_t::OK;
  reply.message.clear();
  reply.num_configurations = query.num_configurations;
  reply.results.assign(static_cast<std::size_t>(query.num_configurations), wrc::contact_result_t{});
  // Each configuration's answer, for the ones that follow it (ContactQuery::follows).
  std::vector<ContactResult> results(static_cast<std::size_t>(query.num_configurations));
  std::vector<const ContactResult*> answered;
  for (int i = 0; i < query.num_configurations; ++i) {
    wrc::contact_result_t& out = reply.results[static_cast<std::size_t>(i)];
    std::int8_t status = wrc::contact_reply_t::OK;
    std::string why;
    const int follows = query.configurations[static_cast<std::size_t>(i)].follows;
    if (follows >= 1 && follows <= i && answered[static_cast<std::size_t>(follows - 1)] == nullptr) {
      // It follows a configuration without an answer: that one's status, which it cannot raise.
      answered.push_back(nullptr);
      reply.results[static_cast<std::size_t>(i)] = wrc::contact_result_t{};
      reply.results[static_cast<std::size_t>(i)].status = reply.results[static_cast<std::size_t>(follows - 1)].status;
      continue;
    }
    try {
      ContactQuery q = protocol::to_contact_query(query, i);
      apply_follows(answered, i, q);
      results[static_cast<std::size_t>(i)] = model.evaluate(q);
      answered.push_back(&results[static_cast<std::size_t>(i)]);
      protocol::to_result_message(results[static_cast<std::size_t>(i)], out);
    } catch (const NoContactError& e) {
      status = wrc::contact_reply_t::NO_CONTACT;
      why = e.what();
    } catch (const OutsideModelError& e) {
      status = wrc::contact_reply_t::OUTSIDE_MODEL;
      why = e.what();
    } catch (const ContactConfigurationError& e) {
      status = wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION;
      why = e.what();
    } catch (const std::invalid_argument& e) {
      status = wrc::contact_reply_t::BAD_REQUEST;
      why = e.what();
    } catch (const std::exception& e) {
      status = wrc::contact_reply_t::INTERNAL_ERROR;
      why = e.what();
    } catch (...) {
      status = wrc::contact_reply_t::INTERNAL_ERROR;
      why = "unknown exception";
    }
    if (status == wrc::contact_reply_t::OK) continue;
    if (answered.size() == static_cast<std::size_t>(i)) answered.push_back(nullptr);  // no answer to follow
    out = wrc::contact_result_t{};
    out.status = status;
    if (protocol::contact_status_severity(status) > protocol::contact_status_severity(reply.status)) {
      reply.status = status;
      reply.message = configuration_label(query.configurations[static_cast<std::size_t>(i)], i) + why;
    }
  }
}

}  // namespace wrc::contactd
