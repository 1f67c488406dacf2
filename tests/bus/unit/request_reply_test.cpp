// SPDX-License-Identifier: Apache-2.0
// Request/reply over memq://: ids echoed, timeouts and retries, stale and duplicate replies
// ignored and counted, bad requests rejected and counted without crashing the server, the reply
// cache keyed on the sending process, unsigned and replayed requests ignored.
#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "bus/auth/signed_publish.hpp"
#include "bus/transport/request_client.hpp"
#include "bus/transport/request_server.hpp"
#include "memq_bus.hpp"
#include "test_bus_key.hpp"
#include "wrc/ping_reply_t.hpp"
#include "wrc/ping_request_t.hpp"

namespace {
using namespace wrc::bus;
using Client = RequestClient<wrc::ping_request_t, wrc::ping_reply_t>;
using Server = RequestServer<wrc::ping_request_t, wrc::ping_reply_t>;

Server::Handler echo_handler(int* calls = nullptr) {
  return [calls](const wrc::ping_request_t& req, wrc::ping_reply_t& rep) {
    if (calls != nullptr) ++*calls;
    if (req.num_payload == 13) throw std::runtime_error("unlucky payload");
    if (req.num_payload == 14) throw std::invalid_argument("payload of 14 bytes is not allowed");
    rep.status = wrc::ping_reply_t::OK;
    rep.num_payload = req.num_payload;
    rep.payload = req.payload;
  };
}

void fill_error(const wrc::ping_request_t&, RequestError kind, const std::string& why, wrc::ping_reply_t& rep) {
  rep.status = kind == RequestError::kBadRequest ? wrc::ping_reply_t::BAD_REQUEST : 99;
  rep.message = why;
}

wrc::ping_request_t ping(int bytes) {
  wrc::ping_request_t req{};
  req.num_payload = bytes;
  req.payload.assign(static_cast<std::size_t>(bytes), 0x5a);
  return req;
}

// A call gets the reply with its own id and the payload echoed, in one attempt.
TEST(RequestReply, EchoesIdAndPayload) {
  lcm::LCM lcm("memq://");
  ASSERT_TRUE(lcm.good());
  Server server(lcm, "PING", "test-server", echo_handler());
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  std::int64_t first_id = 0;
  for (int i = 1; i <= 3; ++i) {
    auto req = ping(10 * i);
    auto result = client.call(req, {0.5, 0});
    ASSERT_TRUE(result);
    if (i == 1) first_id = req.request_id;
    EXPECT_EQ(result.reply->request_id, req.request_id);
    EXPECT_EQ(result.reply->request_id, first_id + i - 1);  // one id per call, counting up
    EXPECT_EQ(result.reply->num_payload, 10 * i);
    EXPECT_EQ(result.attempts, 1);
  }
  EXPECT_EQ(server.counters().answered, 3);
  EXPECT_EQ(client.counters().replies, 3);
}

// Each attempt reads what is queued whatever its timeout: a call with a timeout far below any
// round trip still dispatches every subscription (on memq:// the request, then its reply), so a
// client retrying short calls never stops reading its bus.
TEST(RequestReply, ReadsItsQueueWhateverTheTimeout) {
  lcm::LCM lcm("memq://");
  Server server(lcm, "PING", "test-server", echo_handler());
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  auto req = ping(3);
  auto result = client.call(req, {1e-12, 0});
  ASSERT_TRUE(result);
  EXPECT_EQ(result.reply->num_payload, 3);
  EXPECT_EQ(server.counters().answered, 1);
}

// Without a server every attempt times out; the call reports failure after 1 + retries sends.
TEST(RequestReply, TimesOutAndRetries) {
  lcm::LCM lcm("memq://");
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  auto req = ping(1);
  const double start = monotonic_seconds();
  auto result = client.call(req, {0.02, 2});
  const double elapsed = monotonic_seconds() - start;
  EXPECT_FALSE(result);
  EXPECT_EQ(result.attempts, 3);
  EXPECT_EQ(client.counters().sent, 3);
  EXPECT_EQ(client.counters().retries, 2);
  EXPECT_EQ(client.counters().failed_calls, 1);
  EXPECT_GE(elapsed, 0.06);  // three timeouts of 0.02 s waited in full (a lower bound: causal)
  std::cout << "[ measured ] three attempts of 0.02 s: " << elapsed << " s\n";
  EXPECT_THROW(client.call(req, {0.0, 1}), std::invalid_argument);
  EXPECT_THROW(client.call(req, {0.1, -1}), std::invalid_argument);
}

// A test server that answers each request twice and also sends a reply for an old id.
struct DoubleReplier {
  lcm::LCM& lcm;
  void on_request(const lcm::ReceiveBuffer*, const std::string&, const wrc::ping_request_t* req) {
    wrc::ping_reply_t rep{};
    rep.request_id = req->request_id - 2;  // an older call's id (or an id never used): stale
    publish_signed(lcm, req->reply_channel, rep);
    rep.request_id = req->request_id;
    publish_signed(lcm, req->reply_channel, rep);
    publish_signed(lcm, req->reply_channel, rep);  // duplicate
  }
};

// Replies with an old id are counted stale, a second reply to a completed call duplicate; the
// call still returns the right reply.
TEST(RequestReply, IgnoresStaleAndDuplicateReplies) {
  lcm::LCM lcm("memq://");
  DoubleReplier replier{lcm};
  lcm.subscribe("PING", &DoubleReplier::on_request, &replier);
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  for (int i = 0; i < 3; ++i) {
    auto req = ping(0);
    auto result = client.call(req, {0.5, 0});
    ASSERT_TRUE(result);
    EXPECT_EQ(result.reply->request_id, req.request_id);
  }
  test::drain(lcm);
  EXPECT_EQ(client.counters().replies, 3);
  EXPECT_EQ(client.counters().stale_replies, 3);
  EXPECT_EQ(client.counters().duplicate_replies, 3);
}

// A server that ignores the first request it sees of each payload size given, and answers the
// rest as the echo server does (twice: the second a duplicate).
struct ForgetfulReplier {
  lcm::LCM& lcm;
  std::vector<int> ignore_once;  // payload sizes whose first request goes unanswered
  std::vector<std::int64_t> seen_ids;
  void on_request(const lcm::ReceiveBuffer*, const std::string&, const wrc::ping_request_t* req) {
    seen_ids.push_back(req->request_id);
    for (auto it = ignore_once.begin(); it != ignore_once.end(); ++it) {
      if (*it != req->num_payload) continue;
      ignore_once.erase(it);
      return;
    }
    wrc::ping_reply_t rep{};
    rep.request_id = req->request_id;
    rep.num_payload = req->num_payload;
    rep.payload = req->payload;
    publish_signed(lcm, req->reply_channel, rep);
    publish_signed(lcm, req->reply_channel, rep);
  }
};

// call_each: several calls at once, each with an id of its own, each result the reply to its own
// request; a request without a reply is sent again (same id), the answered ones are not; a second
// reply is a duplicate; one that never gets a reply is an empty result after 1 + retries sends.
TEST(RequestReply, CallEachWaitsForEveryReplyAndResendsOnlyTheMissing) {
  lcm::LCM lcm("memq://");
  ForgetfulReplier replier{lcm, {2}, {}};
  lcm.subscribe("PING", &ForgetfulReplier::on_request, &replier);
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  std::vector<wrc::ping_request_t> requests{ping(1), ping(2), ping(3)};
  std::vector<CallResult<wrc::ping_reply_t>> results = client.call_each(requests.data(), requests.size(), {0.05, 2});
  ASSERT_EQ(results.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_TRUE(results[k]) << k;
    EXPECT_EQ(results[k].reply->request_id, requests[k].request_id) << k;
    EXPECT_EQ(results[k].reply->num_payload, static_cast<int>(k + 1)) << k;
    EXPECT_GT(results[k].round_trip, 0.0) << k;
  }
  EXPECT_NE(requests[0].request_id, requests[1].request_id);
  EXPECT_EQ(results[0].attempts, 1);
  EXPECT_EQ(results[1].attempts, 2);  // its first request was ignored
  EXPECT_EQ(results[2].attempts, 1);
  EXPECT_EQ(replier.seen_ids, (std::vector<std::int64_t>{requests[0].request_id, requests[1].request_id,
                                                         requests[2].request_id, requests[1].request_id}));
  test::drain(lcm);
  EXPECT_EQ(client.counters().calls, 3);
  EXPECT_EQ(client.counters().sent, 4);
  EXPECT_EQ(client.counters().retries, 1);
  EXPECT_EQ(client.counters().replies, 3);
  EXPECT_EQ(client.counters().duplicate_replies, 3);

  lcm::LCM quiet("memq://");
  ForgetfulReplier deaf{quiet, {5, 5, 5}, {}};  // three attempts of size 5 go unanswered
  quiet.subscribe("PING", &ForgetfulReplier::on_request, &deaf);
  Client other(quiet, "PING", "PING_REPLY.c2", "test-client");
  std::vector<wrc::ping_request_t> two{ping(4), ping(5)};
  const auto second = other.call_each(two.data(), two.size(), {0.02, 2});
  EXPECT_TRUE(second[0]);
  EXPECT_FALSE(second[1]);
  EXPECT_EQ(second[1].attempts, 3);
  EXPECT_EQ(other.counters().failed_calls, 1);
  EXPECT_THROW(other.call_each(two.data(), 0, {0.1, 0}), std::invalid_argument);
}

/// Publishes bytes on channel signed under the test key.
void publish_signed_bytes(lcm::LCM& lcm, const std::string& channel, std::vector<std::uint8_t> bytes) {
  bus_auth().sign(channel, bytes);
  lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
}

// Undecodable messages on the request channel, signed or not, are counted and the server keeps
// answering.
TEST(RequestReply, ServerRejectsMalformedMessagesAndKeepsAnswering) {
  lcm::LCM lcm("memq://");
  Server server(lcm, "PING", "test-server", echo_handler());
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  const unsigned char garbage[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  lcm.publish("PING", garbage, sizeof garbage);
  publish_signed_bytes(lcm, "PING", std::vector<std::uint8_t>(garbage, garbage + sizeof garbage));
  wrc::ping_reply_t wrong_type{};
  lcm.publish("PING", &wrong_type);
  publish_signed(lcm, "PING", wrong_type);
  test::drain(lcm);
  EXPECT_EQ(server.counters().rejected, 4);
  auto req = ping(4);
  EXPECT_TRUE(client.call(req, {0.5, 0}));
  EXPECT_EQ(server.counters().answered, 1);
}

// Invalid requests (validator, invalid_argument from the handler) get a BAD_REQUEST reply;
// other handler exceptions an internal-error reply; all are counted as rejections.
TEST(RequestReply, InvalidRequestsGetErrorReplies) {
  lcm::LCM lcm("memq://");
  int calls = 0;
  Server server(lcm, "PING", "test-server", echo_handler(&calls));
  server.set_validator([](const wrc::ping_request_t& r) {
    return r.num_payload > 100 ? "num_payload " + std::to_string(r.num_payload) + " exceeds 100" : std::string();
  });
  server.set_error_filler(fill_error);
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  auto big = ping(101);
  auto r1 = client.call(big, {0.5, 0});
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1.reply->status, wrc::ping_reply_t::BAD_REQUEST);
  EXPECT_EQ(r1.reply->message, "num_payload 101 exceeds 100");
  EXPECT_EQ(calls, 0);
  auto unlucky = ping(13);
  auto r2 = client.call(unlucky, {0.5, 0});
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2.reply->status, 99);
  auto fourteen = ping(14);
  auto r3 = client.call(fourteen, {0.5, 0});
  ASSERT_TRUE(r3);
  EXPECT_EQ(r3.reply->status, wrc::ping_reply_t::BAD_REQUEST);
  EXPECT_EQ(server.counters().rejected, 3);
}

// A re-sent request (same reply channel and id) is answered from the cache, not recomputed.
TEST(RequestReply, ResentRequestAnsweredFromCache) {
  lcm::LCM lcm("memq://");
  int calls = 0;
  Server server(lcm, "PING", "test-server", echo_handler(&calls));
  int replies = 0;
  struct Counter {
    int* n;
    void on(const lcm::ReceiveBuffer*, const std::string&) { ++*n; }
  } counter{&replies};
  lcm.subscribe("R", &Counter::on, &counter);
  auto req = ping(2);
  req.request_id = 5;
  req.reply_channel = "R";
  publish_signed(lcm, "PING", req);
  publish_signed(lcm, "PING", req);  // a retry: signed again, new sequence number
  test::drain(lcm);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(replies, 2);
  EXPECT_EQ(server.counters().from_cache, 1);
}

// Issue 11: request ids restart in every client, and reply channels can be reused. A request
// with the same reply channel and id from another process (another sender nonce) is computed,
// not answered with the first client's cached reply.
TEST(RequestReply, CacheDoesNotAnswerAnotherClientOnAReusedChannel) {
  lcm::LCM lcm("memq://");
  std::vector<int> payload_sizes;
  Server server(lcm, "PING", "test-server", [&](const wrc::ping_request_t& req, wrc::ping_reply_t& rep) {
    payload_sizes.push_back(req.num_payload);
    rep.num_payload = req.num_payload;
    rep.payload = req.payload;
  });
  std::vector<int> replies;
  struct Collector {
    std::vector<int>* sizes;
    void on(const lcm::ReceiveBuffer*, const std::string&, const wrc::ping_reply_t* rep) {
      sizes->push_back(rep->num_payload);
    }
  } collector{&replies};
  lcm.subscribe("R", &Collector::on, &collector);
  auto first = ping(2);
  first.request_id = 1;
  first.reply_channel = "R";
  publish_signed(lcm, "PING", first);
  test::drain(lcm);
  // A second process: same bus key, its own nonce, counting its ids from 1 on the same channel.
  MessageAuth other_process(test::test_bus_key(), MessageAuth::random_nonce());
  auto second = ping(7);
  second.request_id = 1;
  second.reply_channel = "R";
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(second.getEncodedSize()));
  second.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  other_process.sign("PING", bytes);
  lcm.publish("PING", bytes.data(), static_cast<unsigned>(bytes.size()));
  test::drain(lcm);
  EXPECT_EQ(payload_sizes, (std::vector<int>{2, 7}));
  EXPECT_EQ(replies, (std::vector<int>{2, 7}));
  EXPECT_EQ(server.counters().from_cache, 0);
}

// An unsigned request, a request signed under another key and a replayed datagram (the same
// bytes again) reach no handler and get no reply; each is counted as rejected.
TEST(RequestReply, UnsignedForgedAndReplayedRequestsAreIgnored) {
  lcm::LCM lcm("memq://");
  int calls = 0;
  Server server(lcm, "PING", "test-server", echo_handler(&calls));
  auto req = ping(3);
  req.request_id = 9;
  req.reply_channel = "R";
  lcm.publish("PING", &req);  // unsigned
  BusKey other_key;
  other_key.bytes.fill(0x42);
  MessageAuth forger(other_key, 1234);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(req.getEncodedSize()));
  req.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  std::vector<std::uint8_t> forged = bytes;
  forger.sign("PING", forged);
  lcm.publish("PING", forged.data(), static_cast<unsigned>(forged.size()));
  test::drain(lcm);
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(server.counters().rejected, 2);
  std::vector<std::uint8_t> genuine = bytes;
  bus_auth().sign("PING", genuine);
  lcm.publish("PING", genuine.data(), static_cast<unsigned>(genuine.size()));
  lcm.publish("PING", genuine.data(), static_cast<unsigned>(genuine.size()));  // replayed
  test::drain(lcm);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(server.counters().answered, 1);
  EXPECT_EQ(server.counters().from_cache, 0);
  EXPECT_EQ(server.counters().rejected, 3);
}

// Requests for another instance are ignored without being counted as errors.
TEST(RequestReply, AddressFilterIgnoresOtherInstances) {
  lcm::LCM lcm("memq://");
  Server server(lcm, "PING", "test-server", echo_handler());
  server.set_address_filter([](const wrc::ping_request_t& r) { return r.instance.empty() || r.instance == "a"; });
  Client client(lcm, "PING", "PING_REPLY.c1", "test-client");
  auto other = ping(1);
  other.instance = "b";
  EXPECT_FALSE(client.call(other, {0.02, 0}));
  auto mine = ping(1);
  mine.instance = "a";
  EXPECT_TRUE(client.call(mine, {0.5, 0}));
  EXPECT_EQ(server.counters().not_addressed, 1);
  EXPECT_EQ(server.counters().rejected, 0);
}
}  // namespace
