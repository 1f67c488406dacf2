// SPDX-License-Identifier: Apache-2.0
// Every string field of every message has a limit (bus/transport/string_limits.hpp): at its limit
// a message decodes; one byte over, and at 60 kB, it is malformed (kUndecodable) with the field
// named, whichever field of whichever message type; a free-text field is cut to its limit when
// sent, an identifier over its limit is refused naming it.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/decode.hpp"
#include "bus/transport/string_limits.hpp"
#include "wrc/wheelset_states_t.hpp"
#include "bus/auth/message_auth.hpp"

namespace wrc::bus {
namespace {

// The number of strings the visitor reaches in m.
template <class Message>
int string_count(Message& m) {
  int n = 0;
  visit_strings(m, [&](const char*, std::string&, std::size_t, StringKind) { ++n; });
  return n;
}

// m with its k-th string set to length bytes; field receives its name and limit its limit.
template <class Message>
Message with_string(Message m, int k, std::size_t length, std::string& field, std::size_t& limit) {
  int i = 0;
  visit_strings(m, [&](const char* name, std::string& value, std::size_t max, StringKind) {
    if (i++ != k) return;
    value.assign(length, 'x');
    field = name;
    limit = max;
  });
  return m;
}

template <class Message>
std::optional<DecodeFailure> round_trip(const Message& m) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  Message back;
  return decode_bytes(bytes.data(), bytes.size(), back);
}

// For every string of m: accepted at its limit, malformed one byte over and at 60 kB, the reason
// naming the field and its length.
template <class Message>
void expect_every_string_bounded(Message m, int expected_strings) {
  const std::string type = Message::getTypeName();
  ASSERT_FALSE(round_trip(m)) << type;
  ASSERT_EQ(string_count(m), expected_strings) << type;
  for (int k = 0; k < expected_strings; ++k) {
    std::string field;
    std::size_t limit = 0;
    with_string(m, k, 0, field, limit);  // the field's name and limit
    EXPECT_FALSE(round_trip(with_string(m, k, limit, field, limit))) << type << "." << field;
    for (const std::size_t length : {limit + 1, std::size_t{60000}}) {
      const auto failure = round_trip(with_string(m, k, length, field, limit));
      ASSERT_TRUE(failure) << type << "." << field << " of " << length << " bytes";
      EXPECT_EQ(failure->kind, DropKind::kUndecodable);
      EXPECT_NE(failure->reason.find(field + " is " + std::to_string(length) + " bytes, longer than its limit of " +
                                     std::to_string(limit)),
                std::string::npos)
          << failure->reason;
    }
  }
}

TEST(StringLimits, EveryStringOfEveryMessageIsBoundedAtDecoding) {
  expect_every_string_bounded(wrc::contact_query_t{}, 6);
  expect_every_string_bounded(wrc::contact_reply_t{}, 6);
  expect_every_string_bounded(wrc::contact_select_t{}, 4);
  expect_every_string_bounded(wrc::geometry_request_t{}, 6);
  wrc::geometry_table_t table{};
  table.num_columns = 1;
  table.column_names = {"z"};
  table.column_units = {"m"};
  expect_every_string_bounded(table, 12);
  expect_every_string_bounded(wrc::heartbeat_t{}, 8);
  expect_every_string_bounded(wrc::integrator_stats_t{}, 2);
  expect_every_string_bounded(wrc::model_piece_request_t{}, 4);
  expect_every_string_bounded(wrc::model_piece_t{}, 3);
  expect_every_string_bounded(wrc::ping_reply_t{}, 3);
  expect_every_string_bounded(wrc::ping_request_t{}, 3);
  expect_every_string_bounded(wrc::progress_t{}, 3);
  wrc::run_command_t command{};
  command.num_scheduled_swaps = 1;
  command.scheduled_swap_times = {1.0};
  command.scheduled_swap_models = {"spline"};
  command.num_vehicle_bodies = 1;
  command.vehicle_bodies.resize(1);
  command.num_vehicle_elements = 1;
  command.vehicle_elements.resize(1);
  expect_every_string_bounded(command, 16);  // with the vehicle's name, a body's and an element's three
  expect_every_string_bounded(wrc::run_status_t{}, 5);
  wrc::run_summary_t summary{};
  summary.num_swaps = 1;
  summary.swap_times = {1.0};
  summary.swap_models = {"spline"};
  summary.num_query_instances = 1;
  summary.query_instances = {"spline/a"};
  summary.instance_queries = {924};
  summary.num_wheelsets = 1;
  summary.wheelsets.resize(1);
  summary.num_bodies = 1;
  summary.bodies.resize(1);
  expect_every_string_bounded(summary, 11);
  wrc::spline_model_t model{};
  model.num_functions = 1;
  model.function_names = {"z"};
  model.function_units = {"m"};
  expect_every_string_bounded(model, 12);
  expect_every_string_bounded(wrc::wheelset_state_t{}, 3);
  wrc::wheelset_states_t states{};
  states.num_states = 1;
  states.states.resize(1);
  expect_every_string_bounded(states, 5);
}

// Sending: a reason over its limit goes out cut to the limit, ending in "..."; a run id over its
// limit is refused naming the field, before anything is sent.
TEST(StringLimits, FreeTextIsCutWhenSentAndALongIdentifierRefused) {
  wrc::run_status_t status{};
  status.message = std::string(60000, 'r');
  std::vector<std::uint8_t> bytes;
  encode_signed("RUN_STATUS", status, bytes);
  wrc::run_status_t back;
  ASSERT_FALSE(decode_bytes(bytes.data(), bytes.size() - MessageAuth::kTrailerBytes, back));
  EXPECT_EQ(back.message.size(), kMaxTextBytes);
  EXPECT_EQ(back.message.substr(kMaxTextBytes - 4), "r...");
  status.run_id = std::string(kMaxIdBytes + 1, 'i');
  try {
    encode_signed("RUN_STATUS", status, bytes);
    ADD_FAILURE() << "a run id of " << kMaxIdBytes + 1 << " bytes was sent";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "sending a run_status_t on RUN_STATUS: run_id is 129 bytes, longer than its limit of 128");
  }
}

}  // namespace
}  // namespace wrc::bus
