// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/string_limits.hpp"

#include <string>
#include <vector>

#include "bus/transport/channels.hpp"

namespace wrc::bus {
namespace {

constexpr StringKind kId = StringKind::kIdentifier;
constexpr StringKind kText = StringKind::kText;

void visit_header(wrc::header_t& h, const StringVisitor& f) { f("header.sender", h.sender, kMaxIdBytes, kId); }

void visit_profile(const char* name_field, const char* hash_field, wrc::profile_ref_t& p, const StringVisitor& f) {
  f(name_field, p.name, kMaxPathBytes, kId);
  f(hash_field, p.content_hash, kMaxHashBytes, kId);
}

void visit_track(wrc::track_t& t, const StringVisitor& f) {
  visit_profile("track.wheel_profile.name", "track.wheel_profile.content_hash", t.wheel_profile, f);
  visit_profile("track.rail_profile.name", "track.rail_profile.content_hash", t.rail_profile, f);
}

void visit_all(const char* field, std::vector<std::string>& values, std::size_t limit, const StringVisitor& f) {
  for (std::string& v : values) f(field, v, limit, kId);
}

}  // namespace

std::string over_limit_text(const char* field, std::size_t size, std::size_t limit) {
  return std::string(field) + " is " + std::to_string(size) + " bytes, longer than its limit of " +
         std::to_string(limit);
}

void visit_strings(wrc::contact_query_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("client_id", m.client_id, kMaxNameBytes, kId);
  f("reply_channel", m.reply_channel, kMaxChannelLength, kId);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
}

void visit_strings(wrc::contact_reply_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
  f("model_hash", m.model_hash, kMaxHashBytes, kId);
  f("message", m.message, kMaxTextBytes, kText);
}

void visit_strings(wrc::contact_select_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
}

void visit_strings(wrc::geometry_request_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("reply_channel", m.reply_channel, kMaxChannelLength, kId);
  visit_track(m.track, f);
}

void visit_strings(wrc::geometry_table_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
  f("model_key", m.model_key, kMaxHashBytes, kId);
  f("table_hash", m.table_hash, kMaxHashBytes, kId);
  visit_track(m.track, f);
  visit_all("column_names[]", m.column_names, kMaxNameBytes, f);
  visit_all("column_units[]", m.column_units, kMaxNameBytes, f);
  f("file_path", m.file_path, kMaxPathBytes, kId);
  f("file_hash", m.file_hash, kMaxHashBytes, kId);
}

void visit_strings(wrc::heartbeat_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("request_channel", m.request_channel, kMaxChannelLength, kId);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
  f("model_hash", m.model_hash, kMaxHashBytes, kId);
  f("state_reason", m.state_reason, kMaxTextBytes, kText);
  f("activity", m.activity, kMaxTextBytes, kText);
}

void visit_strings(wrc::integrator_stats_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
}

void visit_strings(wrc::model_piece_request_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("model_key", m.model_key, kMaxHashBytes, kId);
  f("file_hash", m.file_hash, kMaxHashBytes, kId);
  f("reply_channel", m.reply_channel, kMaxChannelLength, kId);
}

void visit_strings(wrc::model_piece_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("model_key", m.model_key, kMaxHashBytes, kId);
  f("file_hash", m.file_hash, kMaxHashBytes, kId);
}

void visit_strings(wrc::ping_reply_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("message", m.message, kMaxTextBytes, kText);
}

void visit_strings(wrc::ping_request_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("reply_channel", m.reply_channel, kMaxChannelLength, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
}

void visit_strings(wrc::progress_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("task", m.task, kMaxTextBytes, kText);
  f("message", m.message, kMaxTextBytes, kText);
}

void visit_strings(wrc::run_command_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("dynamics_instance", m.dynamics_instance, kMaxNameBytes, kId);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
  visit_track(m.track, f);
  visit_all("scheduled_swap_models[]", m.scheduled_swap_models, kMaxNameBytes, f);
  f("vehicle_name", m.vehicle_name, kMaxIdBytes, kText);
  for (wrc::vehicle_body_t& b : m.vehicle_bodies) f("vehicle_bodies[].name", b.name, kMaxIdBytes, kId);
  for (wrc::vehicle_element_t& e : m.vehicle_elements) {
    f("vehicle_elements[].name", e.name, kMaxIdBytes, kId);
    f("vehicle_elements[].body_a", e.body_a, kMaxIdBytes, kId);
    f("vehicle_elements[].body_b", e.body_b, kMaxIdBytes, kId);
  }
}

void visit_strings(wrc::run_status_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  f("model", m.model, kMaxNameBytes, kId);
  f("instance", m.instance, kMaxNameBytes, kId);
  f("message", m.message, kMaxTextBytes, kText);
}

void visit_strings(wrc::run_summary_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  f("message", m.message, kMaxTextBytes, kText);
  f("model", m.model, kMaxNameBytes, kId);
  f("formulation", m.formulation, kMaxNameBytes, kId);
  f("stats.header.sender", m.stats.header.sender, kMaxIdBytes, kId);
  f("stats.run_id", m.stats.run_id, kMaxIdBytes, kId);
  visit_all("swap_models[]", m.swap_models, kMaxNameBytes, f);
  visit_all("query_instances[]", m.query_instances, kMaxIdBytes, f);
  for (wrc::wheelset_summary_t& w : m.wheelsets) f("wheelsets[].name", w.name, kMaxIdBytes, kId);
  for (wrc::body_summary_t& b : m.bodies) f("bodies[].name", b.name, kMaxIdBytes, kId);
}

void visit_strings(wrc::spline_model_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("geometry_key", m.geometry_key, kMaxHashBytes, kId);
  f("model_key", m.model_key, kMaxHashBytes, kId);
  f("model_hash", m.model_hash, kMaxHashBytes, kId);
  visit_track(m.track, f);
  visit_all("function_names[]", m.function_names, kMaxNameBytes, f);
  visit_all("function_units[]", m.function_units, kMaxNameBytes, f);
  f("file_path", m.file_path, kMaxPathBytes, kId);
  f("file_hash", m.file_hash, kMaxHashBytes, kId);
}

void visit_strings(wrc::wheelset_state_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  f("model", m.model, kMaxNameBytes, kId);
}

void visit_strings(wrc::wheelset_states_t& m, const StringVisitor& f) {
  visit_header(m.header, f);
  f("run_id", m.run_id, kMaxIdBytes, kId);
  for (wrc::wheelset_state_t& state : m.states) {
    f("states[].header.sender", state.header.sender, kMaxIdBytes, kId);
    f("states[].run_id", state.run_id, kMaxIdBytes, kId);
    f("states[].model", state.model, kMaxNameBytes, kId);
  }
}

}  // namespace wrc::bus
