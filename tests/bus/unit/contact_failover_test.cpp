// SPDX-License-Identifier: Apache-2.0
/// @file
/// Contact queries fail over (services/dynamicsd/bus_contact.hpp), over memq://: an instance that
/// claims to be the leader of its model (READY, the smallest name) and never answers, as a hung
/// process or a key holder's forged heartbeat does, costs the dynamics one round of attempts, not
/// the run. The responder here is instance "b" of onepoint behind the contact service's own
/// leader rule (contactd/instance_filter.hpp), so it answers an unaddressed query only while no
/// READY instance with a smaller name is heard, and every query addressed to it. Also the
/// heartbeat table's two look-ups the fail-over and the leader rule use.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/auth/message_auth.hpp"
#include "bus/auth/signed_publish.hpp"
#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/request_client.hpp"
#include "contactd/instance_filter.hpp"
#include "dynamicsd/bus_contact.hpp"
#include "memq_bus.hpp"
#include "protocol/contact/contact_query_codec.hpp"
#include "test_bus_key.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::dynamics {
namespace {

constexpr const char* kKey = "geometry-key-of-the-run";

// A heartbeat of model/instance in state, signed by a process of its own (nonce).
void publish_heartbeat(lcm::LCM& lcm, const std::string& model, const std::string& instance, std::int8_t state,
                       std::uint64_t nonce, const std::string& geometry_key = kKey, const std::string& model_hash = "") {
  heartbeat_t hb{};
  hb.model = model;
  hb.model_hash = model_hash;
  hb.instance = instance;
  hb.state = state;
  hb.period = 10.0;  // alive for the whole test
  hb.interface_version = heartbeat_t::INTERFACE_VERSION;
  hb.geometry_key = geometry_key;
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(hb.getEncodedSize()));
  hb.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  bus::MessageAuth(bus::test::test_bus_key(), nonce).sign("HEARTBEAT", bytes);
  lcm.publish("HEARTBEAT", bytes.data(), static_cast<unsigned>(bytes.size()));
}

// Instance name (default "b") of onepoint: answers what the leader rule gives it, with one result
// per configuration whose normal force is the configuration's lateral shift (so an answer shows
// which query it belongs to), and its model hash.
class Responder {
 public:
  explicit Responder(lcm::LCM& lcm, std::string name = "b", std::string model_hash = "")
      : lcm_(lcm),
        name_(std::move(name)),
        model_hash_(std::move(model_hash)),
        filter_(lcm, "HEARTBEAT", "onepoint", name_),
        queries_(lcm, "CONTACT_QUERY.onepoint", "test responder",
                 [this](const contact_query_t& q, const bus::ReceivedMessage&) { on_query(q); }) {}
  int unaddressed_seen = 0;
  int answered = 0;
  std::vector<wheelset_configuration_t> seen;  // every configuration answered, in order
  std::function<long()> note;  // called at each query answered, its value kept in noted
  std::vector<long> noted;

 private:
  void on_query(const contact_query_t& q) {
    if (q.instance.empty()) ++unaddressed_seen;
    if (!filter_.answers(q)) return;
    contact_reply_t r{};
    r.request_id = q.request_id;
    r.status = contact_reply_t::OK;
    r.model = "onepoint";
    r.instance = name_;
    r.model_hash = model_hash_;
    r.geometry_key = q.geometry_key;
    r.num_configurations = q.num_configurations;
    r.results.resize(static_cast<std::size_t>(q.num_configurations));
    for (std::size_t k = 0; k < r.results.size(); ++k) {
      r.results[k].num_patches = 1;
      r.results[k].patches.resize(1);
      r.results[k].patches[0].normal_force = q.configurations[k].y;
      r.results[k].wheels[0].s_wheel = 10.0 * q.configurations[k].y;  // the answered point
      seen.push_back(q.configurations[k]);
    }
    ++answered;
    if (note) noted.push_back(note());
    bus::publish_signed(lcm_, q.reply_channel, r);
  }
  lcm::LCM& lcm_;
  std::string name_;
  std::string model_hash_;
  contactd::InstanceFilter filter_;
  bus::GuardedSubscription<contact_query_t> queries_;
};

struct FailoverBus {
  lcm::LCM lcm{"memq://"};
  bus::ChannelNames names{""};
  bus::HeartbeatMonitor monitor{lcm, "HEARTBEAT"};
  bus::RequestClient<contact_query_t, contact_reply_t> client{lcm, "CONTACT_QUERY.onepoint", "CONTACT_REPLY.test",
                                                              "test-dynamics"};
  BusContactSettings settings() const {
    BusContactSettings s;
    s.model = "onepoint";
    s.geometry_key = kKey;
    s.policy = {0.02, 1};  // [s], re-sends: a round is 2 attempts of 20 ms
    s.wait = 1.0;
    return s;
  }
};

std::vector<ContactQuery> one_query(double y) {
  std::vector<ContactQuery> batch(1);
  batch[0].pose.y = y;
  return batch;
}

// A batch whose configurations differ in what a message carries once (here the friction) goes as
// one message per run of configurations that share it; a configuration that follows an earlier one
// (ContactQuery::follows) is renumbered within its message, or, when it follows one of an earlier
// message, that answer's points are followed by the dynamics before it is sent.
TEST(ContactFailover, ASplitBatchKeepsWhatEachConfigurationFollows) {
  FailoverBus bus;
  Responder b(bus.lcm);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 102);
  bus::test::drain(bus.lcm);
  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  std::vector<ContactQuery> batch(4);
  for (std::size_t k = 0; k < batch.size(); ++k) {
    batch[k].pose.y = 0.001 * static_cast<double>(k + 1);
    batch[k].material.friction = k < 2 ? 0.3 : 0.4;
  }
  batch[1].follows = 1;  // the first of the same message
  batch[2].follows = 2;  // the second, in the first message: followed before sending
  batch[3].follows = 3;  // the third, the first of the second message
  const std::vector<ContactResult> r = contact.evaluate(batch);
  ASSERT_EQ(r.size(), 4u);
  for (std::size_t k = 0; k < r.size(); ++k) EXPECT_EQ(r[k].patches[0].normal_force, batch[k].pose.y) << k;
  EXPECT_EQ(b.answered, 2) << "one message per friction";
  ASSERT_EQ(b.seen.size(), 4u);
  EXPECT_EQ(b.seen[0].follows, 0);
  EXPECT_EQ(b.seen[1].follows, 1);
  EXPECT_EQ(b.seen[2].follows, 0);
  EXPECT_EQ(b.seen[2].tracked_s_wheel_left, 10.0 * 0.002) << "configuration 1's answered point";
  EXPECT_EQ(b.seen[3].follows, 1);
}

// A batch longer than a message takes (a vehicle's wheelsets with a Newton matrix each) goes as
// messages of at most protocol::kMaxConfigurations, in order, every answer in its place; a
// configuration that follows one across the cut follows its answer.
TEST(ContactFailover, ABatchLongerThanAMessageGoesAsSeveral) {
  FailoverBus bus;
  Responder b(bus.lcm);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 102);
  bus::test::drain(bus.lcm);
  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  const std::size_t n = 2 * protocol::kMaxConfigurations + 6;
  std::vector<ContactQuery> batch(n);
  for (std::size_t k = 0; k < n; ++k) batch[k].pose.y = 1e-4 * static_cast<double>(k + 1);
  const std::size_t cut = protocol::kMaxConfigurations;  // the first of the second message
  batch[cut].follows = static_cast<int>(cut);             // follows the last of the first message
  const std::vector<ContactResult> r = contact.evaluate(batch);
  ASSERT_EQ(r.size(), n);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(r[k].patches[0].normal_force, batch[k].pose.y) << k;
  EXPECT_EQ(b.answered, 3);
  ASSERT_EQ(b.seen.size(), n);
  EXPECT_EQ(b.seen[cut].follows, 0);
  EXPECT_EQ(b.seen[cut].tracked_s_wheel_left, 10.0 * batch[cut - 1].pose.y);
}

// Where no configuration follows one of another message, a long batch's messages go at once, each
// to the next instance in the turn: every message is sent before any is answered (the client had
// sent as many requests when each was answered), the instances share them, every answer is in its
// place.
TEST(ContactFailover, TheMessagesOfALongBatchGoAtOnceOverTheTurn) {
  FailoverBus bus;
  Responder b(bus.lcm, "b", "hash-1");
  Responder c(bus.lcm, "c", "hash-1");
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 401, kKey, "hash-1");
  publish_heartbeat(bus.lcm, "onepoint", "c", heartbeat_t::READY, 402, kKey, "hash-1");
  bus::test::drain(bus.lcm);
  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  for (int k = 0; k < 2; ++k) contact.evaluate(one_query(1e-3));  // b answers first, then c is probed
  ASSERT_EQ(contact.instance_queries().size(), 2u);
  const long before = b.answered + c.answered;
  b.note = c.note = [&bus] { return static_cast<long>(bus.client.counters().sent); };

  const std::size_t n = 3 * protocol::kMaxConfigurations;
  std::vector<ContactQuery> batch(n);
  for (std::size_t k = 0; k < n; ++k) batch[k].pose.y = 1e-5 * static_cast<double>(k + 1);
  batch[1].follows = 1;  // within the first message
  const std::vector<ContactResult> r = contact.evaluate(batch);
  ASSERT_EQ(r.size(), n);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(r[k].patches[0].normal_force, batch[k].pose.y) << k;
  EXPECT_EQ(b.answered + c.answered - before, 3);
  EXPECT_GE(b.noted.size(), 1u);
  EXPECT_GE(c.noted.size(), 1u);
  std::vector<long> noted = b.noted;
  noted.insert(noted.end(), c.noted.begin(), c.noted.end());
  ASSERT_EQ(noted.size(), 3u);
  EXPECT_EQ(noted[0], noted[1]);
  EXPECT_EQ(noted[1], noted[2]) << "a message was sent after another was answered";
  EXPECT_EQ(contact.retries(), 0);
  EXPECT_EQ(contact.timeouts(), 0);
  const std::map<std::string, long> counted = contact.instance_queries();
  EXPECT_EQ(counted.at("b") + counted.at("c"), 5);
}

// A READY "a" that never answers (the leader by name), and "b" that does: the first query goes to
// both at once and b's answer is taken, so nothing is lost to a; later queries go to b, the only
// instance that has answered, and a is only probed (20 ms, then left out). Without the spreading
// no unaddressed query is answered (the leader rule waits for a).
TEST(ContactFailover, ASilentReadyInstanceCostsNoRound) {
  FailoverBus bus;
  Responder b(bus.lcm);
  publish_heartbeat(bus.lcm, "onepoint", "a", heartbeat_t::READY, 101);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 102);
  bus::test::drain(bus.lcm);
  ASSERT_EQ(bus.monitor.ready_instances("onepoint", kKey, bus::monotonic_seconds()),
            (std::vector<std::string>{"a", "b"}));

  // The leader rule alone: an unaddressed query gets no answer while a is READY.
  contact_query_t bare{};
  std::vector<ContactQuery> batch = one_query(0.001);
  protocol::to_query_message(batch, bare);
  bare.model = "onepoint";
  bare.geometry_key = kKey;
  EXPECT_FALSE(bus.client.call(bare, {0.02, 1}));
  EXPECT_EQ(b.answered, 0);

  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  const std::vector<ContactResult> first = contact.evaluate(one_query(0.002));
  ASSERT_EQ(first.size(), 1u);
  ASSERT_EQ(first[0].patches.size(), 1u);
  EXPECT_EQ(first[0].patches[0].normal_force, 0.002);
  EXPECT_EQ(contact.failovers(), 0);
  EXPECT_EQ(contact.timeouts(), 0);

  for (int k = 1; k <= 20; ++k) {
    const double y = 0.002 + 1e-4 * k;
    const std::vector<ContactResult> r = contact.evaluate(one_query(y));
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].patches[0].normal_force, y);
  }
  EXPECT_EQ(contact.failovers(), 0);
  EXPECT_EQ(contact.timeouts(), 0);
  EXPECT_EQ(contact.retries(), 0);
  EXPECT_EQ(contact.failed_probes(), 1);  // a, once: then left out for BusContact::kProbePause
  EXPECT_EQ(b.answered, 21);
  EXPECT_EQ(contact.instance_queries(), (std::map<std::string, long>{{"b", 21}}));
}

// Two READY instances that answer: the queries go to them in turn, every answer the one to its own
// query, and each counted; a third READY instance computing with another model hash than the first
// answer's (a spline model of another fit) is never asked.
TEST(ContactFailover, QueriesAreSpreadOverTheReadyInstancesOfOneModelHash) {
  FailoverBus bus;
  Responder b(bus.lcm, "b", "hash-1");
  Responder c(bus.lcm, "c", "hash-1");
  Responder d(bus.lcm, "d", "hash-2");
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 301, kKey, "hash-1");
  publish_heartbeat(bus.lcm, "onepoint", "c", heartbeat_t::READY, 302, kKey, "hash-1");
  publish_heartbeat(bus.lcm, "onepoint", "d", heartbeat_t::READY, 303, kKey, "hash-2");
  bus::test::drain(bus.lcm);
  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  for (int k = 0; k < 30; ++k) {
    const double y = 1e-4 * (k + 1);
    const std::vector<ContactResult> r = contact.evaluate(one_query(y));
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].patches[0].normal_force, y);
  }
  EXPECT_EQ(contact.timeouts(), 0);
  EXPECT_EQ(contact.failovers(), 0);
  EXPECT_EQ(contact.failed_probes(), 0);
  // The first query goes to all three at once and b's answer, the first, is taken: hash-1 it is.
  // From then on d, computing with another model hash, is never asked again; c is probed, answers
  // and joins the turn.
  EXPECT_LE(d.answered, 1) << "d computes with another model hash";
  const std::map<std::string, long> counted = contact.instance_queries();
  EXPECT_EQ(counted.count("d"), 0u);
  ASSERT_EQ(counted.size(), 2u);
  EXPECT_EQ(counted.at("b") + counted.at("c"), 30);
  EXPECT_LE(std::abs(counted.at("b") - counted.at("c")), 2);
}

// When the instance with the run's model hash falls silent, an instance that answers with another
// model hash (a spline model of another fit; here its heartbeat even claims the run's hash) is not
// the fail-over: its answers are refused, never mixed in, and the wait ends in an error.
TEST(ContactFailover, AnAnswerOfAnotherModelHashIsRefused) {
  FailoverBus bus;
  BusContactSettings s = bus.settings();
  s.wait = 0.3;
  BusContact contact(bus.client, bus.monitor, bus.names, s);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 601, kKey, "hash-1");
  bus::test::drain(bus.lcm);
  {
    Responder b(bus.lcm, "b", "hash-1");
    contact.evaluate(one_query(0.001));  // hash-1 learned from b
  }  // b falls silent, its heartbeat still READY
  Responder d(bus.lcm, "d", "hash-2");
  publish_heartbeat(bus.lcm, "onepoint", "d", heartbeat_t::READY, 602, kKey, "hash-1");
  bus::test::drain(bus.lcm);
  EXPECT_THROW(contact.evaluate(one_query(0.002)), std::runtime_error);
  EXPECT_GE(d.answered, 1) << "d was asked";
  EXPECT_GE(contact.other_model_answers(), 1);
  EXPECT_EQ(contact.instance_queries(), (std::map<std::string, long>{{"b", 1}}));
}

// A flood of forged READY instances (a key holder's heartbeats) next to the one that answers: each
// is probed at most once per BusContact::kProbeInterval with BusContact::kProbeTimeout, never a
// whole round, and every query is answered by the real one.
TEST(ContactFailover, ForgedReadyInstancesCostAShortProbeEachNotARound) {
  FailoverBus bus;
  Responder b(bus.lcm);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 401);
  bus::test::drain(bus.lcm);
  BusContact contact(bus.client, bus.monitor, bus.names, bus.settings());
  contact.evaluate(one_query(0.001));  // b answers and is in the turn
  for (int k = 0; k < 20; ++k)
    publish_heartbeat(bus.lcm, "onepoint", "forged-" + std::to_string(k), heartbeat_t::READY, 500 + k);
  bus::test::drain(bus.lcm);
  const double start = bus::monotonic_seconds();
  int queries = 0;
  while (bus::monotonic_seconds() < start + 1.0) {
    const double y = 1e-5 * ++queries;
    ASSERT_EQ(contact.evaluate(one_query(y))[0].patches[0].normal_force, y);
  }
  const double elapsed = bus::monotonic_seconds() - start;
  EXPECT_EQ(contact.failovers(), 0);
  EXPECT_GE(contact.failed_probes(), 1);
  // At most one probe per interval (the first at once): a bound on what the flood costs.
  EXPECT_LE(contact.failed_probes(), 1 + static_cast<long>(elapsed / BusContact::kProbeInterval));
  EXPECT_EQ(contact.instance_queries(), (std::map<std::string, long>{{"b", queries + 1}}));
}

// Nobody answers: every round fails over to the READY instances and the wait ends in an error
// naming the model; a named instance (settings.instance) is never failed over from.
TEST(ContactFailover, NoAnswerAnywhereEndsTheWaitWithTheReason) {
  FailoverBus bus;
  publish_heartbeat(bus.lcm, "onepoint", "a", heartbeat_t::READY, 201);
  bus::test::drain(bus.lcm);
  BusContactSettings s = bus.settings();
  s.wait = 0.2;
  BusContact contact(bus.client, bus.monitor, bus.names, s);
  try {
    contact.evaluate(one_query(0.001));
    FAIL() << "no service answered, yet evaluate returned";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no contact service onepoint answered"), std::string::npos) << e.what();
  }
  EXPECT_GE(contact.failovers(), 1);
  EXPECT_EQ(contact.timeouts(), 2 * contact.failovers());  // each round and its fail-over round
  EXPECT_TRUE(contact.addressed_instance().empty());

  Responder b(bus.lcm);
  publish_heartbeat(bus.lcm, "onepoint", "b", heartbeat_t::READY, 202);
  bus::test::drain(bus.lcm);
  // No instance READY at all: each round counts once, none fails over (a round is 2 attempts of
  // 20 ms, so the 0.2 s wait holds at most 6 rounds).
  BusContactSettings none = s;
  none.model = "multipoint";
  BusContact lonely(bus.client, bus.monitor, bus.names, none);
  EXPECT_THROW(lonely.evaluate(one_query(0.001)), std::runtime_error);
  EXPECT_EQ(lonely.failovers(), 0);
  EXPECT_GE(lonely.timeouts(), 1);
  EXPECT_LE(lonely.timeouts(), 6);

  s.instance = "a";  // asked by name: a's silence is the answer, b is not asked
  BusContact named(bus.client, bus.monitor, bus.names, s);
  EXPECT_THROW(named.evaluate(one_query(0.001)), std::runtime_error);
  EXPECT_EQ(named.failovers(), 0);
  EXPECT_EQ(b.answered, 0);
}

// The table's look-ups: ready_instances lists the READY instances of a model with the key, sorted
// and once each (two processes of one name count once), not the other states, models or keys;
// available_before says whether a READY instance with a smaller name is heard.
TEST(ContactFailover, HeartbeatTableLookups) {
  lcm::LCM lcm("memq://");
  bus::HeartbeatMonitor monitor(lcm, "HEARTBEAT");
  publish_heartbeat(lcm, "onepoint", "c", heartbeat_t::READY, 1);
  publish_heartbeat(lcm, "onepoint", "c", heartbeat_t::READY, 2);
  publish_heartbeat(lcm, "onepoint", "b", heartbeat_t::STARTING, 3);
  publish_heartbeat(lcm, "onepoint", "d", heartbeat_t::READY, 4, "another-key");
  publish_heartbeat(lcm, "interp", "a", heartbeat_t::READY, 5);
  publish_heartbeat(lcm, "onepoint", "e", heartbeat_t::READY, 6);
  bus::test::drain(lcm);
  const double now = bus::monotonic_seconds();
  EXPECT_EQ(monitor.ready_instances("onepoint", kKey, now), (std::vector<std::string>{"c", "e"}));
  EXPECT_EQ(monitor.ready_instances("onepoint", "", now), (std::vector<std::string>{"c", "d", "e"}));
  EXPECT_TRUE(monitor.ready_instances("multipoint", "", now).empty());
  EXPECT_FALSE(monitor.available_before("onepoint", "c", now));  // b is only STARTING
  EXPECT_TRUE(monitor.available_before("onepoint", "c0", now));
  EXPECT_FALSE(monitor.available_before("interp", "a", now));
  EXPECT_TRUE(monitor.available_before("interp", "b", now));
  // Past three periods (30 s) nobody is alive any more.
  EXPECT_TRUE(monitor.ready_instances("onepoint", "", now + 31.0).empty());
  EXPECT_FALSE(monitor.available_before("onepoint", "z", now + 31.0));
}

}  // namespace
}  // namespace wrc::dynamics
