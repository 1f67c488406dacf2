// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The longest each string field of each message may be, in one place. A received message with a
/// longer string is malformed (decode_bytes(), bus/transport/decode.hpp: dropped and counted
/// before any handler sees it, so that no handler's cost or log grows with it); a message about
/// to be sent has its free-text fields (reasons, activities, tasks) cut to their limit with
/// "...", and an identifier over its limit is refused (publish_signed(),
/// bus/auth/signed_publish.hpp). The .lcm files state each field's limit.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"
#include "wrc/contact_select_t.hpp"
#include "wrc/geometry_request_t.hpp"
#include "wrc/geometry_table_t.hpp"
#include "wrc/heartbeat_t.hpp"
#include "wrc/integrator_stats_t.hpp"
#include "wrc/model_piece_request_t.hpp"
#include "wrc/model_piece_t.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"
#include "wrc/progress_t.hpp"
#include "wrc/run_command_t.hpp"
#include "wrc/run_status_t.hpp"
#include "wrc/run_summary_t.hpp"
#include "wrc/spline_model_t.hpp"
#include "wrc/wheelset_state_t.hpp"
#include "wrc/wheelset_states_t.hpp"

namespace wrc::bus {

/// [B] a model, instance, client id, formulation, function or column name or unit.
inline constexpr std::size_t kMaxNameBytes = 64;
/// [B] a run id or a header's sender ("<program>/<instance>:<pid>").
inline constexpr std::size_t kMaxIdBytes = 128;
/// [B] a SHA-256 in hex (geometry key, model key, model, table, file and content hashes).
inline constexpr std::size_t kMaxHashBytes = 64;
/// [B] a file path (a model or table file, a profile file).
inline constexpr std::size_t kMaxPathBytes = 4096;
/// [B] a reason, a status message, a task or an activity: free text, cut when sent.
inline constexpr std::size_t kMaxTextBytes = 1024;
// Channels (reply_channel, request_channel): kMaxChannelLength (bus/transport/channels.hpp).

/// Identifiers are refused when too long, free text is cut.
enum class StringKind { kIdentifier, kText };

/// Called for each string of a message: its field name (nested: "header.sender", arrays:
/// "column_names[]"), the string, its limit [B] and kind.
using StringVisitor = std::function<void(const char* field, std::string& value, std::size_t limit, StringKind kind)>;

/// Every string of the message, nested ones included, in declaration order.
void visit_strings(wrc::contact_query_t& m, const StringVisitor& f);
void visit_strings(wrc::contact_reply_t& m, const StringVisitor& f);
void visit_strings(wrc::contact_select_t& m, const StringVisitor& f);
void visit_strings(wrc::geometry_request_t& m, const StringVisitor& f);
void visit_strings(wrc::geometry_table_t& m, const StringVisitor& f);
void visit_strings(wrc::heartbeat_t& m, const StringVisitor& f);
void visit_strings(wrc::integrator_stats_t& m, const StringVisitor& f);
void visit_strings(wrc::model_piece_request_t& m, const StringVisitor& f);
void visit_strings(wrc::model_piece_t& m, const StringVisitor& f);
void visit_strings(wrc::ping_reply_t& m, const StringVisitor& f);
void visit_strings(wrc::ping_request_t& m, const StringVisitor& f);
void visit_strings(wrc::progress_t& m, const StringVisitor& f);
void visit_strings(wrc::run_command_t& m, const StringVisitor& f);
void visit_strings(wrc::run_status_t& m, const StringVisitor& f);
void visit_strings(wrc::run_summary_t& m, const StringVisitor& f);
void visit_strings(wrc::spline_model_t& m, const StringVisitor& f);
void visit_strings(wrc::wheelset_state_t& m, const StringVisitor& f);
void visit_strings(wrc::wheelset_states_t& m, const StringVisitor& f);

/// "<field> is <size> bytes, longer than its limit of <limit>": the words of every string-limit
/// violation, received or about to be sent (size and limit [B]).
std::string over_limit_text(const char* field, std::size_t size, std::size_t limit);

/// The first string of m over its limit, as "<field> is N bytes, longer than its limit of L";
/// nothing when every string is within its limit.
template <class Message>
std::optional<std::string> string_limit_violation(const Message& m) {
  std::optional<std::string> why;
  // The visitor only reads here.
  visit_strings(const_cast<Message&>(m), [&](const char* field, std::string& value, std::size_t limit, StringKind) {
    if (!why && value.size() > limit) why = over_limit_text(field, value.size(), limit);
  });
  return why;
}

/// Cuts every free-text string of m over its limit to the limit (ending in "..."). Returns the
/// first identifier still over its limit, as string_limit_violation() words it; nothing if none.
template <class Message>
std::optional<std::string> clip_text(Message& m) {
  std::optional<std::string> why;
  visit_strings(m, [&](const char* field, std::string& value, std::size_t limit, StringKind kind) {
    if (value.size() <= limit) return;
    if (kind == StringKind::kText) {
      value.resize(limit - 3);
      value += "...";
    } else if (!why) {
      why = over_limit_text(field, value.size(), limit);
    }
  });
  return why;
}

}  // namespace wrc::bus
