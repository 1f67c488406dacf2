// SPDX-License-Identifier: Apache-2.0
// The bus under attack, with real processes in a private network namespace (issue 8): the
// malformed datagrams of the issue neither end nor balloon wrc-contactd; unsigned heartbeats and
// queries are ignored; a replayed message changes nothing; a SIGSTOPped service is restarted by
// `wrc launch` within three heartbeat periods; a second process with the same model and instance
// name refuses to serve. The seeded campaign of 100 000 datagrams over every channel against every
// listening process is every_channel_campaign_test.cpp.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../malformed/malformed_messages.hpp"
#include "bus/transport/clock.hpp"
#include "bus/transport/request_client.hpp"
#include "bus_fixture.hpp"
#include "child_process.hpp"
#include "wrc/contact_reply_t.hpp"

namespace wrc::bus::test {
namespace {

using ContactClient = RequestClient<wrc::contact_query_t, wrc::contact_reply_t>;
constexpr double kPeriod = 0.2;  // [s] heartbeat period of the services started here

/// [kB] peak resident memory of process pid (VmHWM), -1 when unknown.
long peak_rss_kib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

struct ArrivalCounter {
  int count = 0;
  void on(const lcm::ReceiveBuffer*, const std::string&) { ++count; }
};

// The replies within 0.5 s to one ping addressed to instance (request_id, replies on the ping
// reply channel of client).
int ping_replies(lcm::LCM& lcm, const ChannelNames& names, const std::function<bool(double)>& wait,
                 const std::string& instance, std::int64_t request_id, const std::string& client) {
  const std::string reply_channel = names.name(channel::kPingReply, client);
  ArrivalCounter replies;
  auto* sub = lcm.subscribe(regex_escape(reply_channel), &ArrivalCounter::on, &replies);
  wrc::ping_request_t req{};
  req.request_id = request_id;
  req.reply_channel = reply_channel;
  req.instance = instance;
  publish_signed(lcm, names.name(channel::kPing), req);
  wait(0.5);
  lcm.unsubscribe(sub);
  return replies.count;
}

class HardeningTest : public BusTest {
 protected:
  std::unique_ptr<ChildProcess> start_contactd(const std::string& instance, const std::string& log) {
    return std::make_unique<ChildProcess>(
        WRC_CONTACTD_PATH,
        std::vector<std::string>{"--model", "onepoint", "--instance", instance, "--heartbeat-period",
                                 std::to_string(kPeriod)},
        log);
  }
  int ping_replies(const std::string& instance, std::int64_t request_id, const std::string& client) {
    return wrc::bus::test::ping_replies(*lcm_, names_, [this](double t) { return handle_until([] { return false; }, t); },
                                        instance, request_id, client);
  }
  /// One query addressed to instance (empty: any); true when a reply came (5 attempts).
  bool answered(const std::string& instance, double timeout = 0.5) {
    if (!contact_) {
      const std::string id = make_client_id("hardening");
      contact_ = std::make_unique<ContactClient>(*lcm_, names_.name(channel::kContactQuery, "onepoint"),
                                                 names_.name(channel::kContactReply, id), id);
    }
    auto q = sample_query(1);
    q.instance = instance;
    return static_cast<bool>(contact_->call(q, {timeout, 4}));
  }
  std::optional<wrc::heartbeat_t> heartbeat_of(const std::string& model, const std::string& instance) {
    handle_until([] { return false; }, 2.5 * kPeriod);  // a fresh heartbeat
    auto s = monitor_->find(model, instance, monotonic_seconds());
    if (!s) return std::nullopt;
    return s->last;
  }
  void publish_unsigned(const std::string& channel, const std::vector<std::uint8_t>& bytes) {
    lcm_->publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
  }
  std::unique_ptr<ContactClient> contact_;
};

/// Counts the messages arriving on one channel, whatever they are.
// Every malformed message of the issue, signed (it reaches the decoder) and unsigned, three
// times: the service keeps its pid, answers, stays below 100 MB, and counts the drops; `wrc
// status` listening meanwhile exits normally.
TEST_F(HardeningTest, MalformedDatagramsNeitherCrashNorBalloon) {
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd("m", log);
  ASSERT_TRUE(wait_ready("onepoint", "m", 60.0)) << read_text(log);
  const std::string status_log = temp_path("status.log");
  ChildProcess status(WRC_CLI_PATH, {"status", "--duration", "1.0"}, status_log);
  const auto cases = malformed_messages();
  for (int round = 0; round < 3; ++round) {
    for (const auto& m : cases) {
      const std::string channel = m.channel_base == "HEARTBEAT" ? names_.name(channel::kHeartbeat)
                                                                : names_.name(channel::kContactQuery, "onepoint");
      publish_signed_bytes(channel, m.bytes);
      publish_unsigned(channel, m.bytes);
    }
    handle_until([] { return false; }, 0.05);
  }
  EXPECT_TRUE(answered("m")) << read_text(log);
  EXPECT_TRUE(service->running()) << read_text(log);
  int status_exit = -1;
  ASSERT_TRUE(status.wait(5.0, &status_exit));
  EXPECT_TRUE(WIFEXITED(status_exit) && WEXITSTATUS(status_exit) == 0) << read_text(status_log);
  const long rss = peak_rss_kib(service->pid());
  EXPECT_GT(rss, 0);
  EXPECT_LT(rss, 100 * 1024) << "peak RSS " << rss << " kB";
  const auto hb = heartbeat_of("onepoint", "m");
  ASSERT_TRUE(hb);
  const auto query_cases = std::count_if(cases.begin(), cases.end(), [](const auto& m) { return m.channel_base != "HEARTBEAT"; });
  // the query cases reach the request server, the heartbeat cases the instance filter's monitor
  EXPECT_GE(hb->dropped_malformed, 3 * static_cast<std::int64_t>(cases.size()) - 3) << read_text(log);
  EXPECT_GE(hb->dropped_unsigned, 3 * static_cast<std::int64_t>(cases.size()));
  EXPECT_GE(hb->requests_rejected, 3 * query_cases);
  std::cerr << "service peak RSS " << rss << " kB; heartbeat: dropped unsigned " << hb->dropped_unsigned
            << ", malformed " << hb->dropped_malformed << "\n";
}

// An unsigned READY heartbeat of a fake instance "0" (which would lead the model: the smallest
// name) and an unsigned query change nothing: the unaddressed query is answered by "m", the
// unsigned one gets no reply, `wrc status` does not list "0", the heartbeat counts both.
TEST_F(HardeningTest, UnsignedHeartbeatAndQueryAreIgnored) {
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd("m", log);
  ASSERT_TRUE(wait_ready("onepoint", "m", 60.0)) << read_text(log);
  publish_unsigned(names_.name(channel::kHeartbeat), encode_message(sample_heartbeat()));  // READY "0", 3600 s
  const std::string reply_channel = names_.name(channel::kContactReply, "unsigned-test");
  ArrivalCounter replies;
  auto* sub = lcm_->subscribe(regex_escape(reply_channel), &ArrivalCounter::on, &replies);
  auto q = sample_query(1);
  q.request_id = 77;
  q.reply_channel = reply_channel;
  publish_unsigned(names_.name(channel::kContactQuery, "onepoint"), encode_message(q));
  handle_until([] { return false; }, 0.5);
  EXPECT_EQ(replies.count, 0) << "an unsigned query was answered";
  EXPECT_FALSE(monitor_->find("onepoint", "0", monotonic_seconds()).has_value());
  EXPECT_TRUE(answered("")) << "the unaddressed query went unanswered: the fake leader was believed";
  int rc = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " status --duration 0.6 --format csv", &rc);
  EXPECT_EQ(out.find("onepoint,0,"), std::string::npos) << out;
  EXPECT_NE(out.find("onepoint,m,"), std::string::npos) << out;
  const auto hb = heartbeat_of("onepoint", "m");
  ASSERT_TRUE(hb);
  EXPECT_GE(hb->dropped_unsigned, 2);
  lcm_->unsubscribe(sub);
}

// A signed query captured and sent again (twice) is answered once; a captured heartbeat replayed
// after its service stopped does not bring it back in a monitor that saw it; both replays are
// counted in the heartbeat.
TEST_F(HardeningTest, ReplayedMessagesChangeNothing) {
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd("m", log);
  ASSERT_TRUE(wait_ready("onepoint", "m", 60.0)) << read_text(log);
  const std::string reply_channel = names_.name(channel::kContactReply, "replay-test");
  ArrivalCounter replies;
  auto* sub = lcm_->subscribe(regex_escape(reply_channel), &ArrivalCounter::on, &replies);
  auto q = sample_query(1);
  q.request_id = 4242;
  q.reply_channel = reply_channel;
  q.instance = "m";
  auto captured = encode_message(q);
  bus_auth().sign(names_.name(channel::kContactQuery, "onepoint"), captured);
  const std::string query_channel = names_.name(channel::kContactQuery, "onepoint");
  lcm_->publish(query_channel, captured.data(), static_cast<unsigned>(captured.size()));
  ASSERT_TRUE(handle_until([&] { return replies.count == 1; }, 2.0)) << read_text(log);
  lcm_->publish(query_channel, captured.data(), static_cast<unsigned>(captured.size()));
  lcm_->publish(query_channel, captured.data(), static_cast<unsigned>(captured.size()));
  handle_until([] { return false; }, 0.5);
  EXPECT_EQ(replies.count, 1) << "a replayed query was answered";
  lcm_->unsubscribe(sub);

  // A heartbeat of wrc-pingd, captured raw, replayed after the service has stopped.
  struct Capture {
    std::vector<std::uint8_t> last;
    void on(const lcm::ReceiveBuffer* rbuf, const std::string&) {
      const auto* data = static_cast<const std::uint8_t*>(rbuf->data);
      if (rbuf->data_size < MessageAuth::kTrailerBytes) return;
      wrc::heartbeat_t hb;
      if (decode_bytes(data, rbuf->data_size - MessageAuth::kTrailerBytes, hb) || hb.model != "pingd") return;
      if (hb.state == wrc::heartbeat_t::READY) last.assign(data, data + rbuf->data_size);
    }
  } capture;
  auto* hb_sub = lcm_->subscribe(regex_escape(names_.name(channel::kHeartbeat)), &Capture::on, &capture);
  auto pingd = start_pingd("r", kPeriod);
  ASSERT_TRUE(wait_ready("pingd", "r", 5.0));
  handle_until([&] { return !capture.last.empty(); }, 2.0);
  lcm_->unsubscribe(hb_sub);
  ASSERT_FALSE(capture.last.empty()) << "no READY heartbeat of pingd/r captured";
  pingd->signal(SIGKILL);
  ASSERT_TRUE(pingd->wait(2.0));
  handle_until([] { return false; }, 4 * kPeriod);
  ASSERT_FALSE(monitor_->find("pingd", "r", monotonic_seconds())->alive);
  for (int i = 0; i < 3; ++i) {
    lcm_->publish(names_.name(channel::kHeartbeat), capture.last.data(), static_cast<unsigned>(capture.last.size()));
  }
  handle_until([] { return false; }, 0.2);
  EXPECT_FALSE(monitor_->find("pingd", "r", monotonic_seconds())->alive) << "a replayed heartbeat revived pingd/r";
  const auto hb = heartbeat_of("onepoint", "m");
  ASSERT_TRUE(hb);
  EXPECT_GE(hb->dropped_replayed, 2 + 3) << read_text(log);
}

// `wrc launch` restarts a service stopped with SIGSTOP (heartbeats stop, the process stays), and
// says why in its log. The rule is in the service's own heartbeat periods, by the launcher's
// clock: it kills a child whose process state says stopped after hang_periods = 2 periods of
// silence (not before), far sooner than the 20 periods after which silence alone counts; so that
// the new process is up within the 3 periods after which clients call a service dead. Asserted
// from the launcher's log line (the silence it saw, in periods), with a generous deadline of
// 20 periods for the new process's first heartbeat; its time is printed.
TEST_F(HardeningTest, StoppedServiceIsRestartedWithinThreePeriods) {
  const double period = 0.3;
  const std::string profile = temp_path("profile.txt");
  std::ofstream(profile) << "pingd wrc-pingd --instance s --heartbeat-period " << period << "\n";
  const std::string log = temp_path("launch.log");
  ChildProcess launcher(WRC_CLI_PATH, {"launch", "--profile", profile, "--build-dir", WRC_TEST_BUILD_DIR}, log);
  ASSERT_TRUE(wait_ready("pingd", "s", 5.0)) << read_text(log);
  handle_until([] { return false; }, 2 * period);
  const pid_t first = monitor_->find("pingd", "s", monotonic_seconds())->last.pid;
  ASSERT_EQ(::kill(first, SIGSTOP), 0);
  const double stopped_at = monotonic_seconds();
  bool restarted = false;
  handle_until(
      [&] {
        for (const auto& s : monitor_->services(monotonic_seconds())) {
          if (s.last.model == "pingd" && s.last.instance == "s" && s.last.pid != first && s.last_seen > stopped_at) {
            restarted = true;
          }
        }
        return restarted;
      },
      20 * period);
  const double took = monotonic_seconds() - stopped_at;
  ASSERT_TRUE(restarted) << read_text(log);
  EXPECT_TRUE(process_gone(first));
  const std::string text = read_text(log);
  const std::string said = "launch: pingd (pid " + std::to_string(first) + ") sent no heartbeat for ";
  const std::size_t at = text.find(said);
  ASSERT_NE(at, std::string::npos) << text;
  // "... for 0.61 s (2.0 periods of 0.30 s) and is stopped: killing it (SIGKILL)"
  const std::size_t open = text.find('(', at + said.size());
  ASSERT_NE(open, std::string::npos) << text;
  const double periods = std::strtod(text.c_str() + open + 1, nullptr);
  EXPECT_GE(periods, 2.0) << text;
  EXPECT_LT(periods, 20.0) << "killed for silence alone, not as stopped\n" << text;
  EXPECT_NE(text.find("and is stopped: killing it (SIGKILL)"), std::string::npos) << text;
  launcher.signal(SIGINT);
  EXPECT_TRUE(launcher.wait(5.0));
  std::cerr << "[ measured ] SIGSTOP to the new process's first heartbeat: " << took << " s, " << took / period
            << " periods (the launcher killed it after " << periods << " periods of silence)\n";
}

// A second wrc-pingd with the name of a live one refuses to serve (DUPLICATE, with the reason,
// in its heartbeat and log): a ping to the name is answered once; `wrc status` lists both; when
// the older one stops, the newer one serves.
TEST_F(HardeningTest, DuplicateInstanceRefusesToServe) {
  auto older = start_pingd("d", kPeriod);
  ASSERT_TRUE(wait_ready("pingd", "d", 5.0));
  const std::string log = temp_path("newer.log");
  auto newer = start_pingd("d", kPeriod, log);
  std::optional<ServiceStatus> refused;
  ASSERT_TRUE(handle_until(
      [&] {
        for (const auto& s : monitor_->services(monotonic_seconds())) {
          if (s.last.pid == newer->pid() && s.last.state == wrc::heartbeat_t::DUPLICATE) refused = s;
        }
        return refused.has_value();
      },
      5.0))
      << read_text(log);
  EXPECT_NE(refused->last.state_reason.find("instance 'd' of model pingd is already served by wrc-pingd/d:" +
                                            std::to_string(older->pid())),
            std::string::npos)
      << refused->last.state_reason;
  EXPECT_NE(read_text(log).find("refusing to serve: instance 'd'"), std::string::npos) << read_text(log);

  EXPECT_EQ(ping_replies("d", 5, "dup-test"), 1) << "answered by both processes";

  int rc = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " status --duration 0.6", &rc);
  EXPECT_NE(out.find("DUPLICATE"), std::string::npos) << out;
  EXPECT_NE(out.find("DUPLICATE: instance 'd' of model pingd is already served by"), std::string::npos) << out;

  older->signal(SIGTERM);
  ASSERT_TRUE(older->wait(5.0));
  EXPECT_TRUE(wait_ready("pingd", "d", 2.0, older->pid())) << read_text(log);
  EXPECT_TRUE(handle_until([&] { return read_text(log).find("the older holder of the name is gone; serving") != std::string::npos; }, 1.0)) << read_text(log);
}

// A bus-key holder's heartbeat that names a live wrc-pingd's own pid and instance with a start a
// minute earlier (signed, but with the sender identity of this test, not the service's) makes
// it ignore that sender, not stand down: it stays READY throughout, says in its log whose
// heartbeats it ignores and why, and answers a ping once.
TEST_F(HardeningTest, ASpoofedOlderHeartbeatNamingTheServicesPidDoesNotStandItDown) {
  const std::string log = temp_path("victim.log");
  auto victim = start_pingd("v", kPeriod, log);
  ASSERT_TRUE(wait_ready("pingd", "v", 5.0));
  const auto own = monitor_->find("pingd", "v", monotonic_seconds());
  ASSERT_TRUE(own.has_value());
  const std::uint64_t victim_nonce = own->nonce;
  wrc::heartbeat_t forged = own->last;
  forged.started_utime -= 60000000;  // a minute older
  bool stood_down = false;
  const double end = monotonic_seconds() + 8 * kPeriod;
  while (monotonic_seconds() < end) {
    publish_signed(*lcm_, names_.name(channel::kHeartbeat), forged);
    handle_until([] { return false; }, 0.5 * kPeriod);
    for (const ServiceStatus& s : monitor_->processes("pingd", "v", monotonic_seconds()))
      stood_down = stood_down || (s.nonce == victim_nonce && s.last.state != wrc::heartbeat_t::READY);
  }
  EXPECT_FALSE(stood_down) << read_text(log);
  const std::string text = read_text(log);
  EXPECT_EQ(text.find("refusing to serve"), std::string::npos) << text;
  EXPECT_NE(text.find("ignoring heartbeats of wrc-pingd/v:" + std::to_string(victim->pid()) + " (pid " +
                      std::to_string(victim->pid()) + "): they name this process's pid under another sender identity"),
            std::string::npos)
      << text;
  EXPECT_EQ(ping_replies("v", 6, "spoof-test"), 1);
}

}  // namespace
}  // namespace wrc::bus::test
