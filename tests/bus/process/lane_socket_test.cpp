// SPDX-License-Identifier: Apache-2.0
// A lane read from a socket of wrc's own (bus/transport/lane_socket.hpp) against plain LCM objects
// publishing on it: short messages byte for byte with LCM's receive stamp, a message long enough
// for LCM to send it in fragments put back together, channels nobody reads ignored, datagrams in
// another format dropped and counted, a signed request and its reply with both ends on lane
// sockets (as wrc-contactd and wrc-dynamicsd use them), and URLs that cannot be a lane refused by
// name.
#include "bus/transport/lane_socket.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bus/transport/clock.hpp"
#include "bus/transport/lcm_url.hpp"
#include "bus/transport/request_server.hpp"
#include "bus_fixture.hpp"

namespace wrc::bus::test {
namespace {

class LaneSocketTest : public BusTest {
 protected:
  void SetUp() override {
    BusTest::SetUp();
    url_ = lane_lcm_url(effective_lcm_url(""), 3);
    ASSERT_FALSE(url_.empty());
    sender_ = std::make_unique<lcm::LCM>(url_);
    ASSERT_TRUE(sender_->good());
  }

  /// Reads the lane until pred() or timeout [s].
  bool read_until(LaneSocket& lane, const std::function<bool()>& pred, double timeout) {
    const double deadline = monotonic_seconds() + timeout;
    while (!pred() && monotonic_seconds() < deadline) {
      if (lane.handle_timeout(20) < 0) return false;
    }
    return pred();
  }

  std::string url_;
  std::unique_ptr<lcm::LCM> sender_;  // a plain LCM object on the lane, as the senders are
};

struct Received {
  std::string channel;
  std::vector<std::uint8_t> data;
  std::int64_t utime = 0;
};

TEST_F(LaneSocketTest, ReadsShortAndFragmentedMessagesAsLcmSendsThem) {
  LaneSocket lane(url_);
  std::vector<Received> got;
  lane.subscribe("A", [&](const lcm::ReceiveBuffer& b, const std::string& c) {
    const auto* p = static_cast<const std::uint8_t*>(b.data);
    got.push_back({c, std::vector<std::uint8_t>(p, p + b.data_size), b.recv_utime});
  });
  std::vector<std::uint8_t> small(1000);
  for (std::size_t k = 0; k < small.size(); ++k) small[k] = static_cast<std::uint8_t>(k * 7);
  // 200 000 B: above LCM's short-message limit of 65 499 B, so LCM sends 4 fragments.
  std::vector<std::uint8_t> large(200000);
  for (std::size_t k = 0; k < large.size(); ++k) large[k] = static_cast<std::uint8_t>(k * 13 + k / 256);
  const std::int64_t before = wall_utime();
  ASSERT_EQ(sender_->publish("B", small.data(), static_cast<unsigned>(small.size())), 0);  // nobody reads B
  ASSERT_EQ(sender_->publish("A", small.data(), static_cast<unsigned>(small.size())), 0);
  ASSERT_EQ(sender_->publish("A", large.data(), static_cast<unsigned>(large.size())), 0);
  ASSERT_TRUE(read_until(lane, [&] { return got.size() == 2; }, 5.0)) << "got " << got.size() << " messages";
  const std::int64_t after = wall_utime();
  EXPECT_EQ(got[0].channel, "A");
  EXPECT_EQ(got[0].data, small);
  EXPECT_EQ(got[1].data, large);
  for (const Received& r : got) {
    EXPECT_GE(r.utime, before - 1000) << "the kernel's receive stamp, wall clock [us]";
    EXPECT_LE(r.utime, after + 1000);
  }
  ASSERT_TRUE(read_until(lane, [&] { return lane.counters().unsubscribed == 1; }, 2.0));
  EXPECT_EQ(lane.counters().messages, 2);
  EXPECT_EQ(lane.counters().datagrams, 1 + 1 + 4);
  EXPECT_EQ(lane.counters().malformed, 0);
}

TEST_F(LaneSocketTest, DatagramsInAnotherFormatAreCountedAndDropped) {
  LaneSocket lane(url_);
  int delivered = 0;
  lane.subscribe("A", [&](const lcm::ReceiveBuffer&, const std::string&) { ++delivered; });
  const int raw = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(raw, 0);
  const std::size_t colon = url_.rfind(':');
  const int port = std::stoi(url_.substr(colon + 1));
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(static_cast<std::uint16_t>(port));
  ASSERT_EQ(inet_pton(AF_INET, url_.substr(7, colon - 7).c_str(), &to.sin_addr), 1);
  const auto send = [&](std::vector<std::uint8_t> bytes) {
    ASSERT_EQ(::sendto(raw, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to),
              static_cast<ssize_t>(bytes.size()));
  };
  send({1, 2, 3});                                  // shorter than a header
  send({0xde, 0xad, 0xbe, 0xef, 0, 0, 0, 1, 'A'});  // another magic number
  std::vector<std::uint8_t> unterminated = {'L', 'C', '0', '2', 0, 0, 0, 2};
  unterminated.insert(unterminated.end(), 100, 'A');  // a channel name with no end
  send(unterminated);
  // a fragment claiming bytes beyond its message
  send({'L', 'C', '0', '3', 0, 0, 0, 3, 0, 0, 0, 4, 0, 0, 0, 2, 0, 1, 0, 2, 9, 9, 9, 9});
  send({'L', 'C', '0', '2', 0, 0, 0, 4, 'A', 0, 42});  // and a good one after them
  ::close(raw);
  ASSERT_TRUE(read_until(lane, [&] { return delivered == 1; }, 5.0));
  EXPECT_EQ(lane.counters().malformed, 4);
  EXPECT_EQ(lane.counters().messages, 1);
}

TEST_F(LaneSocketTest, ASignedRequestAndItsReplyTravelBetweenLaneSockets) {
  // The service reads its query lane from a socket and answers through an LCM object on the reply
  // lane; the client reads the reply lane from a socket and asks through an LCM object on the query
  // lane, as wrc-contactd and wrc-dynamicsd do.
  const std::string reply_url = lane_lcm_url(effective_lcm_url(""), 4);
  LaneSocket query_lane(url_);
  LaneSocket reply_lane(reply_url);
  lcm::LCM reply_sender(reply_url);
  ASSERT_TRUE(reply_sender.good());
  RequestServer<wrc::ping_request_t, wrc::ping_reply_t> server(
      query_lane, "PING", "test-server", [](const wrc::ping_request_t& q, wrc::ping_reply_t& r) {
        r.instance = "lane";
        r.num_payload = q.num_payload;
        r.payload = q.payload;
      });
  server.reply_on(reply_sender);
  PingClient client(reply_lane, "PING", "PING_REPLY_lane", "test-client");
  client.publish_on(*sender_);
  client.also_dispatch(query_lane);  // the service is read in this thread too, while the client waits
  for (int i = 0; i < 50; ++i) {
    wrc::ping_request_t q{};
    q.num_payload = i;
    q.payload.assign(static_cast<std::size_t>(i), static_cast<std::uint8_t>(i));
    auto result = client.call(q, {0.5, 2});
    ASSERT_TRUE(result) << "call " << i;
    EXPECT_EQ(result.reply->payload, q.payload);
    EXPECT_EQ(result.reply->instance, "lane");
    EXPECT_GT(result.receipt_utime, 0) << "the reply's kernel receive stamp";
  }
  EXPECT_EQ(server.counters().answered, 50);
  EXPECT_EQ(client.counters().retries, 0);
}

TEST(LaneSocketUrl, UrlsThatCannotBeALaneAreRefusedByName) {
  for (const std::string& url : {std::string("memq://"), std::string("udpm://239.255.76.67"),
                                 std::string("udpm://10.0.0.1:7668"), std::string("udpm://239.255.76.67:http"),
                                 std::string("udpm://239.255.76.67:7668?recv_buf_size=-1")}) {
    try {
      LaneSocket lane(url);
      ADD_FAILURE() << url << " was opened";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(url), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace wrc::bus::test
