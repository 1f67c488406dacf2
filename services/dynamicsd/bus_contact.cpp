// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/bus_contact.hpp"

#include <algorithm>
#include <stdexcept>

#include "bus/transport/channels.hpp"
#include "bus/transport/clock.hpp"
#include "core/model_interface/followed_points.hpp"
#include "protocol/contact/contact_query_codec.hpp"

namespace wrc::dynamics {

BusContact::BusContact(bus::RequestClient<contact_query_t, contact_reply_t>& client,
                       const bus::HeartbeatMonitor& monitor, const bus::ChannelNames& names,
                       BusContactSettings settings)
    : client_(client),
      monitor_(monitor),
      request_channel_(names.name(bus::channel::kContactQuery, settings.model)),
      settings_(std::move(settings)) {}

std::vector<ContactResult> BusContact::evaluate(const std::vector<ContactQuery>& batch) {
  // A message carries formulation, material and grid once (each configuration its own speed, which
  // on a curve depends on y), and at most protocol::kMaxConfigurations configurations (its reply
  // stays one datagram): a batch whose queries differ in them, or a longer one, goes as one message
  // per run of at most that many queries that share them.
  const auto most = static_cast<std::size_t>(protocol::kMaxConfigurations);
  std::vector<std::pair<std::size_t, std::size_t>> messages;  // [begin, end) of each
  for (std::size_t begin = 0; begin < batch.size();) {
    std::size_t end = begin + 1;
    while (end < batch.size() && end - begin < most && protocol::shares_query_fields(batch[begin], batch[end])) ++end;
    messages.emplace_back(begin, end);
    begin = end;
  }
  if (messages.size() == 1) return evaluate_message(batch);
  // Several messages at once, each to the next instance in the turn, where none follows a
  // configuration of another message (its answer would be needed before it is sent).
  bool independent = settings_.instance.empty();
  for (const auto& [begin, end] : messages)
    for (std::size_t k = begin; k < end && independent; ++k)
      independent = batch[k].follows == 0 || static_cast<std::size_t>(batch[k].follows - 1) >= begin;
  if (independent) {
    refresh_instances(bus::monotonic_seconds());
    if (!turn_.empty()) return evaluate_at_once(batch, messages);
  }
  std::vector<ContactResult> out;
  out.reserve(batch.size());
  for (const auto& [begin, end] : messages) {
    std::vector<ContactResult> part = evaluate_message(message_queries(batch, begin, end, out));
    for (ContactResult& r : part) out.push_back(std::move(r));
  }
  return out;
}

std::vector<ContactQuery> BusContact::message_queries(const std::vector<ContactQuery>& batch, std::size_t begin,
                                                      std::size_t end, const std::vector<ContactResult>& answered) {
  std::vector<ContactQuery> queries(batch.begin() + static_cast<std::ptrdiff_t>(begin),
                                    batch.begin() + static_cast<std::ptrdiff_t>(end));
  for (ContactQuery& q : queries) {
    if (q.follows == 0) continue;
    const std::size_t followed = static_cast<std::size_t>(q.follows - 1);
    if (followed < begin) {  // one of an earlier message, answered: followed here
      follow_answered_points(answered.at(followed), q.tracked_s_wheel, q.second_tracked_s_wheel);
      q.follows = 0;
    } else {
      q.follows -= static_cast<int>(begin);  // one of this message
    }
  }
  return queries;
}

std::vector<ContactResult> BusContact::evaluate_at_once(const std::vector<ContactQuery>& batch,
                                                        const std::vector<std::pair<std::size_t, std::size_t>>& messages) {
  std::vector<contact_query_t> queries(messages.size());
  for (std::size_t m = 0; m < messages.size(); ++m) {
    protocol::to_query_message(message_queries(batch, messages[m].first, messages[m].second, {}), queries[m]);
    queries[m].model = settings_.model;
    queries[m].geometry_key = settings_.geometry_key;
    turn_last_ = (turn_last_ + 1) % turn_.size();
    queries[m].instance = turn_[turn_last_];
  }
  client_.set_request_channel(request_channel_);
  std::vector<bus::CallResult<contact_reply_t>> replies = client_.call_each(queries.data(), queries.size(), settings_.policy);
  std::vector<ContactResult> out;
  out.reserve(batch.size());
  for (std::size_t m = 0; m < messages.size(); ++m) {
    bus::CallResult<contact_reply_t>& result = replies[m];
    retries_ += std::max(result.attempts - 1, 0);
    const auto& [begin, end] = messages[m];
    std::vector<ContactResult> part;
    if (result && !of_another_model(result)) {
      add_times(result);
      part = take_reply(*result.reply, end - begin);
    } else {
      if (!result) {  // silent for a whole round
        ++timeouts_;
        pause(queries[m].instance);
      }
      part = evaluate_message(message_queries(batch, begin, end, out));  // with its fail-over
    }
    for (ContactResult& r : part) out.push_back(std::move(r));
  }
  return out;
}

void BusContact::add_times(const bus::CallResult<contact_reply_t>& result) {
  const contact_reply_t& reply = *result.reply;
  times_.round_trip += result.round_trip;
  times_.send += result.send_time;
  times_.compute += reply.compute_time;
  if (reply.query_receipt_utime <= 0 || result.receipt_utime <= 0) return;  // a service that does not say
  const auto seconds = [](std::int64_t us) { return 1e-6 * static_cast<double>(us); };
  times_.transfer += seconds(reply.query_receipt_utime - result.sent_utime);
  times_.service_wakeup += reply.service_wakeup_time;
  // The reply's header is stamped at the end of the evaluation, before encoding and signing.
  times_.reply += seconds(result.receipt_utime - reply.header.utime);
  times_.client_wakeup += seconds(result.handled_utime - result.receipt_utime);
}

void BusContact::refresh_instances(double now) {
  if (now < refresh_at_) return;
  refresh_at_ = now + kSpreadRefresh;
  std::vector<std::string> turn;
  candidates_.clear();
  for (const std::string& name : monitor_.ready_instances(settings_.model, settings_.geometry_key, now, model_hash_)) {
    const auto paused = paused_until_.find(name);
    if (paused != paused_until_.end() && now < paused->second) continue;
    if (std::find(turn_.begin(), turn_.end(), name) != turn_.end()) {
      turn.push_back(name);
    } else {
      candidates_.push_back(name);
    }
  }
  turn_ = std::move(turn);
}

bus::CallResult<contact_reply_t> BusContact::ask_all(const contact_query_t& query,
                                                     const std::vector<std::string>& instances) {
  std::vector<contact_query_t> copies(instances.size(), query);
  for (std::size_t k = 0; k < instances.size(); ++k) copies[k].instance = instances[k];
  bus::CallResult<contact_reply_t> result = client_.call_any(copies.data(), copies.size(), settings_.policy);
  retries_ += result.attempts - 1;
  return result;
}

bool BusContact::of_another_model(const bus::CallResult<contact_reply_t>& result) {
  if (model_hash_.empty() || result.reply->model_hash == model_hash_) return false;
  // Computed with another model (another spline fit): not an answer of this run's model.
  ++other_model_answers_;
  pause(result.reply->instance);
  return true;
}

void BusContact::pause(const std::string& instance) {
  paused_until_[instance] = bus::monotonic_seconds() + kProbePause;
  refresh_at_ = 0.0;
  turn_.erase(std::remove(turn_.begin(), turn_.end(), instance), turn_.end());
}

BusContact::Target BusContact::spread_target() {
  const double now = bus::monotonic_seconds();
  refresh_instances(now);
  if (turn_.empty()) return {addressed_, false};  // nobody has answered yet: see evaluate_message
  if (!candidates_.empty() && now >= next_probe_) {
    next_probe_ = now + kProbeInterval;
    return {candidates_.front(), true};
  }
  turn_last_ = (turn_last_ + 1) % turn_.size();
  return {turn_[turn_last_], false};
}

std::vector<ContactResult> BusContact::evaluate_message(const std::vector<ContactQuery>& batch) {
  contact_query_t query{};
  protocol::to_query_message(batch, query);
  query.model = settings_.model;
  query.instance = settings_.instance;
  query.geometry_key = settings_.geometry_key;
  client_.set_request_channel(request_channel_);
  const double give_up = bus::monotonic_seconds() + settings_.wait;
  for (;;) {
    if (settings_.instance.empty()) {
      const Target target = spread_target();
      query.instance = target.instance;
      if (target.probe) {
        bus::CallResult<contact_reply_t> probed = client_.call(query, {kProbeTimeout, 0});
        if (probed && !of_another_model(probed)) {
          add_times(probed);
          return take_reply(*probed.reply, batch.size());
        }
        if (!probed) ++failed_probes_;
        pause(target.instance);
        query.instance = spread_target().instance;  // the turn, at once
      }
    }
    bus::CallResult<contact_reply_t> result;
    if (settings_.instance.empty() && turn_.empty() && query.instance.empty() && !candidates_.empty()) {
      // Nobody has answered this client yet: the query goes to every candidate at once, the first
      // answer taken, so that a silent one (hung, or a forged heartbeat) costs nothing.
      result = ask_all(query, candidates_);
    } else {
      result = client_.call(query, settings_.policy);
      retries_ += result.attempts - 1;
    }
    if (!result && settings_.instance.empty()) {
      if (!query.instance.empty()) pause(query.instance);  // silent for a whole round
      // Fail-over: the same query to every READY instance with the run's model hash by name, the
      // first answer taken.
      addressed_.clear();
      const std::vector<std::string> ready =
          monitor_.ready_instances(settings_.model, settings_.geometry_key, bus::monotonic_seconds(), model_hash_);
      if (!ready.empty()) {
        ++timeouts_;  // the round without a reply before it (a fail-over round that fails counts below)
        ++failovers_;
        result = ask_all(query, ready);
        if (result) addressed_ = result.reply->instance;
      }
    }
    if (result && of_another_model(result)) result = {};
    if (result) {
      add_times(result);
      return take_reply(*result.reply, batch.size());
    }
    ++timeouts_;
    if (settings_.keepalive) settings_.keepalive();
    if (bus::monotonic_seconds() >= give_up)
      throw std::runtime_error("no contact service " + settings_.model + " answered within " +
                               std::to_string(settings_.wait) + " s (" +
                               missing_service_reason(monitor_, settings_.model, settings_.instance,
                                                      settings_.geometry_key) +
                               ")");
  }
}

std::vector<ContactResult> BusContact::take_reply(const contact_reply_t& reply, std::size_t expected) {
  const std::string who = "contact model " + settings_.model + " (" + reply.instance + ")";
  if (!settings_.geometry_key.empty() && reply.geometry_key != settings_.geometry_key)
    throw std::runtime_error(who + " computes with geometry key " + reply.geometry_key + ", not " +
                             settings_.geometry_key);
  switch (reply.status) {
    case contact_reply_t::OK: break;
    case contact_reply_t::OUTSIDE_MODEL: throw OutsideModelError(who + ": " + reply.message);
    case contact_reply_t::NO_CONTACT:
    case contact_reply_t::IMPOSSIBLE_CONFIGURATION: throw ContactConfigurationError(who + ": " + reply.message);
    default:
      throw std::runtime_error(who + " answered status " + std::to_string(reply.status) + ": " + reply.message);
  }
  if (reply.results.size() != expected)
    throw std::runtime_error(who + " answered " + std::to_string(reply.results.size()) + " results for " +
                             std::to_string(expected) + " configurations");
  if (model_hash_.empty() && !reply.model_hash.empty()) {
    model_hash_ = reply.model_hash;  // only instances computing with this model are asked
    refresh_at_ = 0.0;
  }
  if (!reply.instance.empty() && std::find(turn_.begin(), turn_.end(), reply.instance) == turn_.end()) {
    turn_.insert(std::upper_bound(turn_.begin(), turn_.end(), reply.instance), reply.instance);
    candidates_.erase(std::remove(candidates_.begin(), candidates_.end(), reply.instance), candidates_.end());
  }
  ++answered_by_[reply.instance];
  std::vector<ContactResult> out;
  out.reserve(expected);
  for (const contact_result_t& r : reply.results) out.push_back(protocol::from_result_message(r));
  return out;
}

std::string missing_service_reason(const bus::HeartbeatMonitor& monitor, const std::string& model,
                                   const std::string& instance, const std::string& geometry_key) {
  const std::string name = model + (instance.empty() ? "" : " instance " + instance);
  std::string reason = "no " + name + " service on the bus";
  for (const bus::ServiceStatus& s : monitor.services(bus::monotonic_seconds())) {
    if (s.last.model != model || (!instance.empty() && s.last.instance != instance) || !s.alive) continue;
    if (!s.available()) {
      reason = "the " + name + " service is not READY";
    } else if (!geometry_key.empty() && s.last.geometry_key != geometry_key) {
      reason = "the " + name + " service computes with geometry key " + s.last.geometry_key.substr(0, 12) +
               "..., not " + geometry_key.substr(0, 12) + "...";
    } else {
      return {};
    }
  }
  return reason;
}

}  // namespace wrc::dynamics
