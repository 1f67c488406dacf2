// SPDX-License-Identifier: Apache-2.0
// wrc-contactd as real processes on a real udpm bus (private network namespace, clients/lib/netns.sh):
// every model answers exactly as the in-process model does (the service adds nothing), invalid
// and impossible queries get error replies naming the cause, malformed messages are counted while
// the service keeps answering, only one instance answers a query, and `wrc launch` / `wrc status`
// / `wrc query` work with the contact services. Every wait has a deadline; building the
// interpolated model takes a while, so READY is awaited for up to kBuildDeadline.
#include <signal.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>

#include "bus/transport/clock.hpp"
#include "bus_fixture.hpp"
#include "core/identity/geometry_key.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/profile/profile_factory.hpp"
#include "protocol/geometry/spline_model_codec.hpp"
#include "protocol/geometry/spline_model_file.hpp"
#include "wrc/contact_query_t.hpp"
#include "wrc/contact_reply_t.hpp"
#include "wrc/heartbeat_t.hpp"

namespace wrc::bus::test {
namespace {

constexpr double kBuildDeadline = 240.0;  // [s] until a started contact service is READY
using ContactClient = RequestClient<wrc::contact_query_t, wrc::contact_reply_t>;

// The expectation comes first: the library query of one test configuration, in which every field
// has a value of its own (no two rates, loads or FASTSIM counts equal, none zero), so a message
// mapping that drops or swaps fields cannot reproduce the in-process result.
ContactQuery library_query(double y, double roll, double yaw, double z,
                           ContactFormulation formulation = ContactFormulation::kRigid) {
  ContactQuery q;
  q.pose.y = y;
  q.pose.z = z;
  q.pose.roll = roll;
  q.pose.yaw = yaw;
  q.y_dot = 0.01;
  q.z_dot = -0.004;
  q.roll_dot = 0.0017;
  q.yaw_dot = -0.002;
  q.speed = 30.0;
  q.spin_rate = 30.0 / 0.46;
  q.normal_load = {154715.0 / 2.0 + 3000.0, 154715.0 / 2.0 - 3000.0};
  q.formulation = formulation;
  q.material = {8.2e10, 0.28, 0.3};
  q.fastsim_elements = 24;
  q.fastsim_strips = 16;
  return q;
}

// The message of a batch, written by hand from the library queries (library -> message, the
// opposite direction of the adapter under test). Batch-wide fields come from the first query.
wrc::contact_query_t make_query(const std::string& model, const std::vector<ContactQuery>& batch) {
  const ContactQuery& first = batch.at(0);
  wrc::contact_query_t q{};
  q.model = model;
  q.formulation = first.formulation == ContactFormulation::kElastic ? wrc::contact_query_t::ELASTIC
                                                                    : wrc::contact_query_t::RIGID;
  q.shear_modulus = first.material.shear_modulus;
  q.poisson_ratio = first.material.poisson_ratio;
  q.friction = first.material.friction;
  q.fastsim_elements = first.fastsim_elements;
  q.fastsim_strips = first.fastsim_strips;
  q.num_configurations = static_cast<std::int32_t>(batch.size());
  for (const ContactQuery& l : batch) {
    wrc::wheelset_configuration_t c{};
    c.y = l.pose.y;
    c.z = l.pose.z;
    c.roll = l.pose.roll;
    c.yaw = l.pose.yaw;
    c.y_dot = l.y_dot;
    c.z_dot = l.z_dot;
    c.roll_dot = l.roll_dot;
    c.yaw_dot = l.yaw_dot;
    c.spin_rate = l.spin_rate;
    c.speed = l.speed;
    c.normal_load_left = l.normal_load[0];
    c.normal_load_right = l.normal_load[1];
    q.configurations.push_back(c);
  }
  return q;
}

void expect_close(double service, double local, const std::string& what) {
  const double tol = 1e-12 * std::max(std::abs(service), std::abs(local));
  EXPECT_LE(std::abs(service - local), tol) << what << ": service " << service << ", in-process " << local;
}

class ContactServiceTest : public BusTest {
 protected:
  std::unique_ptr<ChildProcess> start_contactd(const std::string& model, const std::string& instance,
                                               const std::string& log = "") {
    return std::make_unique<ChildProcess>(
        WRC_CONTACTD_PATH, std::vector<std::string>{"--model", model, "--instance", instance, "--heartbeat-period", "0.1"},
        log);
  }
  ContactClient& client(const std::string& model) {
    if (!contact_client_ || contact_client_->request_channel() != names_.name(channel::kContactQuery, model)) {
      const std::string id = make_client_id("ctest");
      contact_client_ = std::make_unique<ContactClient>(*lcm_, names_.name(channel::kContactQuery, model),
                                                        names_.name(channel::kContactReply, id), id);
    }
    return *contact_client_;
  }
  /// One query, answered within a few retries (the service is READY).
  wrc::contact_reply_t ask(const std::string& model, wrc::contact_query_t query) {
    auto result = client(model).call(query, {2.0, 3});
    EXPECT_TRUE(result) << "no reply from " << model;
    if (!result) return {};
    EXPECT_EQ(result.reply->request_id, query.request_id);
    return *result.reply;
  }
  /// Waits until model/instance is READY, giving up early when the child ended (its log says why).
  bool wait_ready_while(const std::string& model, const std::string& instance, ChildProcess& child) {
    return handle_until(
        [&] {
          auto s = monitor_->find(model, instance, monotonic_seconds());
          return (s && s->available()) || process_gone(child.pid());
        },
        kBuildDeadline) &&
           !process_gone(child.pid());
  }
  std::unique_ptr<ContactClient> contact_client_;
};

// ---- every model: the reply is the in-process result, bit for bit up to 1e-12 ----------------

class EveryModel : public ContactServiceTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(EveryModel, AnswersLikeTheInProcessModel) {
  const std::string model = GetParam();
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd(model, "t", log);
  auto geometry = std::make_shared<const WheelsetGeometry>(make_profile("S1002", ProfileSide::kWheel),
                                                           make_profile("UIC60", ProfileSide::kRail));
  auto local = make_contact_model(model, geometry, ContactModelOptions{});
  ASSERT_TRUE(wait_ready_while(model, "t", *service)) << read_text(log);
  const wrc::heartbeat_t heartbeat = monitor_->find(model, "t", monotonic_seconds())->last;
  EXPECT_EQ(heartbeat.geometry_key, geometry_key(GeometrySpec{}));
  // Only the interpolated model has precomputed data (its table); the others publish no hash.
  EXPECT_EQ(heartbeat.model_hash.size(), model == "interp" ? 64u : 0u) << heartbeat.model_hash;

  // A rigid batch (centred, shifted both ways, yawed, rolled), then an elastic one.
  const std::vector<ContactQuery> rigid_batch = {library_query(0.0, 0.0, 0.0, 0.46), library_query(0.003, 0.0, 0.001, 0.46),
                                                 library_query(-0.004, 0.0005, -0.002, 0.46),
                                                 library_query(0.006, 0.0, 0.0, 0.46)};
  std::vector<ContactQuery> elastic_batch = {library_query(0.0, 0.0, 0.0, 0.0, ContactFormulation::kElastic),
                                             library_query(0.002, 0.0, 0.0, 0.0, ContactFormulation::kElastic)};
  for (ContactQuery& c : elastic_batch) {  // lower the touching wheelset by 0.1 mm
    WheelsetPose pose{c.pose.y, 0.46, c.pose.roll, c.pose.yaw, 0.0};
    double gap = 1e300;
    for (WheelSide side : {WheelSide::kLeft, WheelSide::kRight}) gap = std::min(gap, geometry->common_point(side, pose)->distance);
    c.pose.z = 0.46 - gap - 1e-4;
  }
  const auto rigid = make_query(model, rigid_batch);
  const auto elastic = make_query(model, elastic_batch);
  int patches_compared = 0;
  for (auto* query : {&rigid, &elastic}) {
    const std::vector<ContactQuery>& batch = query == &rigid ? rigid_batch : elastic_batch;
    const wrc::contact_reply_t reply = ask(model, *query);
    EXPECT_EQ(reply.model, model);
    EXPECT_EQ(reply.instance, "t");
    EXPECT_EQ(reply.geometry_key, heartbeat.geometry_key);
    EXPECT_EQ(reply.model_hash, heartbeat.model_hash);
    ASSERT_EQ(reply.num_configurations, query->num_configurations) << reply.message;
    ASSERT_EQ(reply.results.size(), static_cast<std::size_t>(query->num_configurations));
    for (int i = 0; i < query->num_configurations; ++i) {
      const auto& got = reply.results[static_cast<std::size_t>(i)];
      const std::string where = model + " " + (query == &rigid ? "rigid" : "elastic") + " configuration " + std::to_string(i);
      ContactResult want;
      std::int8_t want_status = wrc::contact_reply_t::OK;
      try {
        want = local->evaluate(batch[static_cast<std::size_t>(i)]);
      } catch (const OutsideModelError&) {
        want_status = wrc::contact_reply_t::OUTSIDE_MODEL;
      } catch (const ContactConfigurationError&) {
        want_status = wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION;
      }
      ASSERT_EQ(got.status, want_status) << where << ": " << reply.message;
      ASSERT_EQ(got.num_patches, static_cast<std::int32_t>(want.patches.size())) << where;
      ASSERT_EQ(got.patches.size(), want.patches.size()) << where;
      for (std::size_t k = 0; k < want.patches.size(); ++k) {
        const auto& m = got.patches[k];
        const auto& p = want.patches[k];
        const std::string pw = where + " patch " + std::to_string(k);
        EXPECT_EQ(m.wheel, p.point.side == WheelSide::kLeft ? wrc::contact_patch_t::LEFT : wrc::contact_patch_t::RIGHT);
        expect_close(m.s_wheel, p.point.s, pw + " s");
        expect_close(m.s_rail, p.point.s_rail, pw + " s_rail");
        for (int j = 0; j < 3; ++j) {
          expect_close(m.wheel_point[j], p.point.wheel_point[j], pw + " wheel_point");
          expect_close(m.rail_point[j], p.point.rail_point[j], pw + " rail_point");
          expect_close(m.normal[j], p.point.normal[j], pw + " normal");
        }
        expect_close(m.contact_angle, p.point.contact_angle, pw + " angle");
        expect_close(m.rolling_radius, p.point.rolling_radius, pw + " rolling radius");
        expect_close(m.a, p.a, pw + " a");
        expect_close(m.b, p.b, pw + " b");
        expect_close(m.penetration, p.penetration, pw + " penetration");
        expect_close(m.normal_force, p.normal_force, pw + " normal force");
        expect_close(m.creepage_x, p.creepages.longitudinal, pw + " xi_x");
        expect_close(m.creepage_y, p.creepages.lateral, pw + " xi_y");
        expect_close(m.spin_creepage, p.creepages.spin, pw + " spin");
        expect_close(m.fx, p.forces.fx, pw + " fx");
        expect_close(m.fy, p.forces.fy, pw + " fy");
        expect_close(m.mz, p.forces.mz, pw + " mz");
        ++patches_compared;
      }
      for (int j = 0; j < 3; ++j) {
        expect_close(got.force[j], want.force[j], where + " force");
        expect_close(got.moment[j], want.moment[j], where + " moment");
      }
    }
  }
  EXPECT_GE(patches_compared, 8) << "too few patches: both wheels of the rigid batch should touch";

  // The heartbeat reports the load.
  ASSERT_TRUE(handle_until(
      [&] {
        auto s = monitor_->find(model, "t", monotonic_seconds());
        return s && s->last.requests_handled >= 2 && s->last.latency_mean > 0.0;
      },
      3.0));
  const auto hb = monitor_->find(model, "t", monotonic_seconds())->last;
  EXPECT_GT(hb.latency_p95, 0.0);
  EXPECT_GE(hb.latency_max, hb.latency_p95);
  service->signal(SIGTERM);
  int status = -1;
  ASSERT_TRUE(service->wait(5.0, &status));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  const std::string text = read_text(log);
  EXPECT_NE(text.find("built the " + model + " model in"), std::string::npos) << text;
  EXPECT_NE(text.find("p50"), std::string::npos) << text;
}

// Flange climbed over (y = 50 mm): IMPOSSIBLE_CONFIGURATION overall and for that configuration
// only, with the model's reason (interp: OUTSIDE_MODEL, y lies beyond its table); the other
// configuration of the batch is answered.
TEST_P(EveryModel, FlangeClimbIsImpossibleConfiguration) {
  const std::string model = GetParam();
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd(model, "i", log);
  ASSERT_TRUE(wait_ready_while(model, "i", *service)) << read_text(log);
  const auto reply = ask(model, make_query(model, {library_query(0.001, 0.0, 0.0, 0.46), library_query(0.05, 0.0, 0.0, 0.46)}));
  const std::int8_t expected =
      model == "interp" ? wrc::contact_reply_t::OUTSIDE_MODEL : wrc::contact_reply_t::IMPOSSIBLE_CONFIGURATION;
  EXPECT_EQ(reply.status, expected) << reply.message;
  ASSERT_EQ(reply.num_configurations, 2);
  EXPECT_EQ(reply.results[0].status, wrc::contact_reply_t::OK);
  EXPECT_EQ(reply.results[1].status, expected);
  EXPECT_EQ(reply.results[1].num_patches, 0);
  EXPECT_NE(reply.message.find("configuration 1 (y=0.05"), std::string::npos) << reply.message;
}

INSTANTIATE_TEST_SUITE_P(ContactService, EveryModel, ::testing::Values("onepoint", "interp", "multipoint"));

// ---- error replies -------------------------------------------------------------------------------

// NaN and out-of-range fields, a bad batch size, an unknown formulation, another model's name or
// another geometry: BAD_REQUEST with a message naming the field and its value; never silence.
TEST_F(ContactServiceTest, InvalidQueriesGetBadRequestNamingTheField) {
  auto service = start_contactd("onepoint", "e");
  ASSERT_TRUE(wait_ready_while("onepoint", "e", *service));
  struct Case {
    std::function<void(wrc::contact_query_t&)> spoil;
    std::string expected;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Case> cases{
      {[&](auto& q) { q.configurations[0].y = nan; }, "configurations[0].y = nan"},
      {[&](auto& q) { q.configurations[1].spin_rate = nan; }, "configurations[1].spin_rate = nan"},
      {[&](auto& q) { q.configurations[0].yaw = 0.9; }, "configurations[0].yaw = 0.9 is outside"},
      {[&](auto& q) { q.configurations[1].normal_load_left = -5.0; }, "configurations[1].normal_load_left = -5"},
      {[&](auto& q) { q.configurations[1].speed = 0.0; }, "configurations[1].speed = 0 is not positive"},
      {[&](auto& q) { q.poisson_ratio = nan; }, "poisson_ratio = nan"},
      {[&](auto& q) { q.fastsim_elements = 0; }, "fastsim_elements = 0"},
      {[&](auto& q) { q.formulation = 7; }, "formulation = 7 is neither RIGID (0) nor ELASTIC (1)"},
      {[&](auto& q) { q.num_configurations = 0; q.configurations.clear(); }, "num_configurations = 0 is outside [1, 32]"},
      {[&](auto& q) { q.num_configurations = 33; q.configurations.resize(33, q.configurations[0]); },
       "num_configurations = 33 is outside [1, 32]"},
      {[&](auto& q) { q.model = "interp"; }, "model = 'interp' but this service runs 'onepoint'"},
      {[&](auto& q) { q.geometry_key = "0123456789abcdef"; }, "geometry_key = '0123456789abcdef'"},
  };
  for (const auto& c : cases) {
    auto q = make_query("onepoint", {library_query(0.0, 0.0, 0.0, 0.46), library_query(0.001, 0.0, 0.0, 0.46)});
    c.spoil(q);
    const auto reply = ask("onepoint", q);
    EXPECT_EQ(reply.status, wrc::contact_reply_t::BAD_REQUEST) << c.expected;
    EXPECT_NE(reply.message.find(c.expected), std::string::npos) << "message '" << reply.message << "'";
    EXPECT_EQ(reply.num_configurations, 0);
  }
  // still answering
  EXPECT_EQ(ask("onepoint", make_query("onepoint", {library_query(0.0, 0.0, 0.0, 0.46)})).status, wrc::contact_reply_t::OK);
}

// Wrong type, truncated and garbage bytes on CONTACT_QUERY.onepoint are rejected and counted (in
// the heartbeat and the log); the service keeps answering.
TEST_F(ContactServiceTest, MalformedMessagesRejectedAndCounted) {
  const std::string log = temp_path("contactd.log");
  auto service = start_contactd("onepoint", "m", log);
  ASSERT_TRUE(wait_ready_while("onepoint", "m", *service)) << read_text(log);
  const std::string channel = names_.name(channel::kContactQuery, "onepoint");
  wrc::heartbeat_t other_type{};
  publish_signed(*lcm_, channel, other_type);
  auto q = make_query("onepoint", {library_query(0.0, 0.0, 0.0, 0.46)});
  q.request_id = 99;
  q.reply_channel = "CONTACT_REPLY.nobody";
  std::vector<unsigned char> bytes(static_cast<std::size_t>(q.getEncodedSize()));
  q.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  publish_signed_bytes(channel, {bytes.begin(), bytes.begin() + static_cast<long>(bytes.size() - 9)});
  const unsigned char garbage[] = {0xde, 0xad, 0xbe, 0xef};
  publish_signed_bytes(channel, {garbage, garbage + sizeof garbage});

  const auto reply = ask("onepoint", make_query("onepoint", {library_query(0.001, 0.0, 0.0, 0.46)}));
  EXPECT_EQ(reply.status, wrc::contact_reply_t::OK) << reply.message;
  ASSERT_TRUE(handle_until(
      [&] {
        auto s = monitor_->find("onepoint", "m", monotonic_seconds());
        return s && s->last.requests_rejected >= 3;
      },
      5.0))
      << "the heartbeat does not report the 3 rejections";
  EXPECT_EQ(monitor_->find("onepoint", "m", monotonic_seconds())->last.requests_rejected, 3);
  EXPECT_TRUE(service->running());
  service->signal(SIGTERM);
  ASSERT_TRUE(service->wait(5.0));
  const std::string text = read_text(log);
  EXPECT_NE(text.find("fingerprint mismatch"), std::string::npos) << text;
  EXPECT_NE(text.find("truncated or corrupt contact_query_t"), std::string::npos) << text;
  EXPECT_NE(text.find("too short"), std::string::npos) << text;
}

// ---- instances -----------------------------------------------------------------------------------

// Two instances of one model: an addressed query is answered by that instance only; a query for
// any instance by exactly one (the smallest name), never by both.
TEST_F(ContactServiceTest, OneAnswerPerQueryWithTwoInstances) {
  auto a = start_contactd("onepoint", "a");
  auto b = start_contactd("onepoint", "b");
  ASSERT_TRUE(wait_ready_while("onepoint", "a", *a));
  ASSERT_TRUE(wait_ready_while("onepoint", "b", *b));
  handle_until([] { return false; }, 0.5);  // both have heard each other's READY heartbeat
  const std::string id = make_client_id("twice");
  const std::string reply_channel = names_.name(channel::kContactReply, id);
  struct Counter {
    std::vector<std::string> instances;
    void on(const lcm::ReceiveBuffer*, const std::string&, const wrc::contact_reply_t* r) { instances.push_back(r->instance); }
  } counter;
  auto* sub = lcm_->subscribe(regex_escape(reply_channel), &Counter::on, &counter);
  const std::string channel = names_.name(channel::kContactQuery, "onepoint");
  for (const std::string instance : {"b", "a", ""}) {
    for (int i = 0; i < 5; ++i) {
      counter.instances.clear();
      auto q = make_query("onepoint", {library_query(0.0005 * i, 0.0, 0.0, 0.46)});
      q.request_id = 100 + i + (instance.empty() ? 50 : instance == "a" ? 20 : 0);
      q.reply_channel = reply_channel;
      q.instance = instance;
      publish_signed(*lcm_, channel, q);
      handle_until([&] { return false; }, 0.15);  // collect every reply that comes
      ASSERT_EQ(counter.instances.size(), 1u) << "instance '" << instance << "' query " << i;
      EXPECT_EQ(counter.instances[0], instance.empty() ? "a" : instance);
    }
  }
  lcm_->unsubscribe(sub);
}

// ---- the spline model: wrc-geometryd and wrc-contactd --model spline ------------------------------

// The whole chain over the bus: the spline service starts first and waits (STARTING, asking
// wrc-geometryd); wrc-geometryd starts later, fits and publishes; the service checks and loads the
// model, goes READY with the model's hash in its heartbeat, and answers exactly as the in-process
// SplineModel built from the cached model file (to 1e-12), the reply carrying the same hash.
TEST_F(ContactServiceTest, SplineServiceGetsItsModelFromALateGeometryService) {
  const std::string cache = temp_path("models");
  ::setenv("WRC_CACHE_DIR", cache.c_str(), 1);
  const std::string log = temp_path("spline.log");
  auto spline = start_contactd("spline", "s", log);
  ASSERT_TRUE(handle_until([&] { return monitor_->find("spline", "s", monotonic_seconds()).has_value(); }, 10.0));
  handle_until([] { return false; }, 1.0);
  auto waiting = monitor_->find("spline", "s", monotonic_seconds());
  ASSERT_TRUE(waiting && waiting->alive);
  EXPECT_EQ(waiting->last.state, wrc::heartbeat_t::STARTING) << "READY without a model";
  const std::string geometry_log = temp_path("geometryd.log");
  ChildProcess geometryd(WRC_GEOMETRYD_PATH, {"--instance", "g", "--heartbeat-period", "0.2"}, geometry_log);
  ASSERT_TRUE(wait_ready_while("spline", "s", *spline)) << read_text(log) << read_text(geometry_log);
  ::unsetenv("WRC_CACHE_DIR");

  // The model the service loaded is the cached file's (same key the service asked for).
  const GeometrySpec spec;
  const std::string key = protocol::model_key(geometry_key(spec), SplineFitOptions{});
  const auto model = protocol::decode_model(protocol::read_model_file(cache + "/" + key + ".splinemodel"));
  const std::string hash = model->data_hash();
  EXPECT_EQ(monitor_->find("spline", "s", monotonic_seconds())->last.model_hash, hash);

  const std::vector<ContactQuery> batch = {library_query(0.003, 0.0002, 0.001, 0.46),
                                          library_query(-0.0045, -0.0004, 0.0, 0.46), library_query(0.0065, 0.0, 0.0, 0.46)};
  const auto query = make_query("spline", batch);
  const auto reply = ask("spline", query);
  EXPECT_EQ(reply.model_hash, hash);
  ASSERT_EQ(reply.num_configurations, 3);
  const auto local = make_contact_model("spline", std::make_shared<const WheelsetGeometry>(make_geometry(spec)),
                                        ContactModelOptions{}, ContactModelData{model});
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(reply.results[static_cast<size_t>(i)].status, wrc::contact_reply_t::OK) << reply.message;
    const ContactResult want = local->evaluate(batch[static_cast<size_t>(i)]);
    const auto& got = reply.results[static_cast<size_t>(i)];
    ASSERT_EQ(got.patches.size(), want.patches.size());
    for (size_t k = 0; k < want.patches.size(); ++k) {
      expect_close(got.patches[k].s_wheel, want.patches[k].point.s, "s");
      expect_close(got.patches[k].a, want.patches[k].a, "a");
      expect_close(got.patches[k].fy, want.patches[k].forces.fy, "fy");
    }
  }
  // y = 6.5 mm lies beyond the box (|y| <= 6 mm): OUTSIDE_MODEL, naming y and the box.
  EXPECT_EQ(reply.results[2].status, wrc::contact_reply_t::OUTSIDE_MODEL);
  EXPECT_EQ(reply.status, wrc::contact_reply_t::OUTSIDE_MODEL);
  EXPECT_NE(reply.message.find("y = 0.0065 m not in [-0.006, 0.006] m"), std::string::npos) << reply.message;
}

// `wrc launch` starts wrc-geometryd and the spline service (default profile lines), and
// `wrc query --model spline` is answered by them.
TEST_F(ContactServiceTest, LaunchBringsUpTheSplineServiceAndQueryUsesIt) {
  const std::string cache = temp_path("models");
  ::setenv("WRC_CACHE_DIR", cache.c_str(), 1);
  const std::string log = temp_path("launch.log");
  const auto launcher = launch({"geometry", "contact-spline"}, log);
  handle_until([&] { auto s = monitor_->find("spline", "a", monotonic_seconds()); return s && s->available(); },
               kBuildDeadline);
  ::unsetenv("WRC_CACHE_DIR");
  ASSERT_TRUE(wait_ready("spline", "a", 0.0)) << read_text(log);
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) +
                                          " query --model spline --y 0.003 --roll 0.0002 --load 80000 --format csv 2>&1",
                                      &status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("spline instance a answered"), std::string::npos) << out;
  EXPECT_NE(out.find("\nleft,"), std::string::npos) << out;
  EXPECT_NE(out.find("\nright,"), std::string::npos) << out;
  launcher->signal(SIGINT);
  ASSERT_TRUE(launcher->wait(10.0, &status)) << read_text(log);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
}

// ---- the front end -------------------------------------------------------------------------------

// `wrc launch` with the default profile starts the three contact services; `wrc status` lists them.
TEST_F(ContactServiceTest, LaunchStartsTheContactServicesAndStatusListsThem) {
  const std::string log = temp_path("launch.log");
  const auto launcher = launch({"contact-onepoint", "contact-interp", "contact-multipoint"}, log);
  for (const char* model : {"onepoint", "interp", "multipoint"}) {
    const std::string failed = std::string("cannot build the ") + model + " model";
    handle_until(
        [&] {
          auto s = monitor_->find(model, "a", monotonic_seconds());
          return (s && s->available()) || read_text(log).find(failed) != std::string::npos;
        },
        kBuildDeadline);
    ASSERT_TRUE(wait_ready(model, "a", 0.0)) << model << " not READY\n" << read_text(log);
  }
  int status = -1;
  const std::string out = run_command(std::string(WRC_CLI_PATH) + " status --duration 1.2 --format csv", &status);
  EXPECT_EQ(status, 0);
  for (const char* model : {"onepoint", "interp", "multipoint"}) {
    EXPECT_NE(out.find(std::string(model) + ",a,"), std::string::npos) << out;
    EXPECT_NE(out.find(",READY,1,"), std::string::npos) << out;
    EXPECT_NE(out.find(std::string(",CONTACT_QUERY.") + model + ",\"serving " + model + " queries, "), std::string::npos) << out;
    EXPECT_NE(out.find("," + geometry_key(GeometrySpec{}).substr(0, 12) + ","), std::string::npos) << out;
  }
  launcher->signal(SIGINT);
  ASSERT_TRUE(launcher->wait(10.0, &status)) << read_text(log);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(log);
}

// `wrc query` with no service running starts one, prints the header and one row per patch
// (both wheels of a centred wheelset), and stops the service again; with a service running it
// asks that one; an impossible configuration exits non-zero with the status and reason.
TEST_F(ContactServiceTest, QueryCommandPrintsPatches) {
  const std::string cli = std::string(WRC_CLI_PATH) + " query --build-dir " + WRC_TEST_BUILD_DIR;
  int status = -1;
  std::string out = run_command(cli + " --model onepoint --y 0.001 --format csv 2>" + temp_path("q1.err"), &status);
  const std::string err = read_text(temp_path("q1.err"));
  ASSERT_EQ(status, 0) << out << err;
  EXPECT_EQ(out.rfind("wheel,s,angle,a,b,penetration,normal_force,fx,fy,mz,", 0), 0u) << out;
  EXPECT_NE(out.find(",lateral_curvature_floored\n"), std::string::npos) << out;  // conformal patches flagged
  EXPECT_NE(out.find("\nleft,"), std::string::npos) << out;
  EXPECT_NE(out.find("\nright,"), std::string::npos) << out;
  EXPECT_NE(err.find("starting"), std::string::npos) << err;
  ASSERT_TRUE(handle_until(
      [&] {
        for (const auto& s : monitor_->services(monotonic_seconds())) {
          if (s.last.model == "onepoint" && s.alive) return false;
        }
        return true;
      },
      5.0))
      << "the started service still runs";

  auto service = start_contactd("onepoint", "r");
  ASSERT_TRUE(wait_ready_while("onepoint", "r", *service));
  out = run_command(cli + " --model onepoint --y -0.002 --yaw 0.001 --format table 2>" + temp_path("q2.err"), &status);
  const std::string err2 = read_text(temp_path("q2.err"));
  ASSERT_EQ(status, 0) << out << err2;
  EXPECT_NE(out.find("normal_force"), std::string::npos) << out;
  EXPECT_EQ(err2.find("starting"), std::string::npos) << err2;
  EXPECT_NE(err2.find("instance r answered"), std::string::npos) << err2;
  // The library's edges, which the command checks by the service's own rule, are answered.
  out = run_command(cli + " --model onepoint --y 0.001 --poisson 0.4999 --grid 2x400 --shear-modulus 1e13 "
                          "--speed 1000 --friction 10 --format csv 2>&1",
                    &status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("\nleft,"), std::string::npos) << out;

  out = run_command(cli + " --model onepoint --y 0.001 --instance zz 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(out.find("no READY instance 'zz' of model onepoint"), std::string::npos) << out;
  out = run_command(cli + " --model onepoint 2>&1", &status);
  EXPECT_NE(status, 0);
  EXPECT_NE(out.find("--y"), std::string::npos) << out;
}

// `wrc query` outside the models' range: the wheelset 160 mm into the rails (elastic) is
// IMPOSSIBLE_CONFIGURATION naming the penetration, one lifted 100 mm is NO_CONTACT, a rigid z far
// from contact is refused; each exits non-zero with the reason. A yaw beyond 0.06 rad and a stray
// single-dash word are usage errors.
TEST_F(ContactServiceTest, QueryCommandRefusesOutOfRange) {
  const std::string cli = std::string(WRC_CLI_PATH) + " query --build-dir " + WRC_TEST_BUILD_DIR;
  auto service = start_contactd("onepoint", "r");
  ASSERT_TRUE(wait_ready_while("onepoint", "r", *service));
  int status = -1;
  std::string out = run_command(cli + " --model onepoint --y 0.003 --formulation elastic --z 0.3 2>&1", &status);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << out;
  EXPECT_NE(out.find("IMPOSSIBLE_CONFIGURATION"), std::string::npos) << out;
  EXPECT_NE(out.find("penetration"), std::string::npos) << out;
  out = run_command(cli + " --model onepoint --y 0.003 --formulation elastic --z 0.56 2>&1", &status);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << out;
  EXPECT_NE(out.find("NO_CONTACT"), std::string::npos) << out;
  EXPECT_NE(out.find("lifted"), std::string::npos) << out;
  out = run_command(cli + " --model onepoint --y 0.003 --z 0.56 2>&1", &status);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << out;
  EXPECT_NE(out.find("IMPOSSIBLE_CONFIGURATION"), std::string::npos) << out;
  EXPECT_NE(out.find("beyond +-25 mm"), std::string::npos) << out;
  out = run_command(cli + " --model onepoint --y 0.003 --yaw 0.1 2>&1", &status);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << out;
  EXPECT_NE(out.find("--yaw"), std::string::npos) << out;
  out = run_command(cli + " --model onepoint --y 0.003 -yaw 0.05 2>&1", &status);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) != 0) << out;
  EXPECT_NE(out.find("unexpected argument '-yaw'"), std::string::npos) << out;
}

// With two READY instances, `wrc query` asks the smallest name even when the other one (beating five
// times as often) is heard first.
TEST_F(ContactServiceTest, QueryCommandPicksTheSmallestInstance) {
  auto later = start_contactd("onepoint", "b");
  ASSERT_TRUE(wait_ready_while("onepoint", "b", *later));
  auto smallest = std::make_unique<ChildProcess>(
      WRC_CONTACTD_PATH, std::vector<std::string>{"--model", "onepoint", "--instance", "a", "--heartbeat-period", "0.5"});
  ASSERT_TRUE(wait_ready_while("onepoint", "a", *smallest));
  const std::string cli = std::string(WRC_CLI_PATH) + " query --build-dir " + WRC_TEST_BUILD_DIR;
  for (int i = 0; i < 3; ++i) {
    int status = -1;
    const std::string err = temp_path("pick" + std::to_string(i) + ".err");
    const std::string out = run_command(cli + " --model onepoint --y 0.001 2>" + err, &status);
    ASSERT_EQ(status, 0) << out << read_text(err);
    EXPECT_NE(read_text(err).find("instance a answered"), std::string::npos) << read_text(err);
  }
}

// A `wrc query` ended by a signal while the service it started is loading leaves no log behind.
TEST_F(ContactServiceTest, KilledQueryRemovesItsServiceLog) {
  for (int sig : {SIGTERM, SIGINT}) {
    const std::string err = temp_path("killed" + std::to_string(sig) + ".err");
    ChildProcess query(WRC_CLI_PATH,
                       {"query", "--build-dir", WRC_TEST_BUILD_DIR, "--model", "interp", "--y", "0.001"}, err);
    std::string log;
    ASSERT_TRUE(handle_until(
        [&] {
          const std::string text = read_text(err);
          const auto at = text.find("(log ");
          const auto end = text.find(')', at);
          if (at == std::string::npos || end == std::string::npos) return false;
          log = text.substr(at + 5, end - at - 5);
          return std::ifstream(log).good();
        },
        10.0))
        << read_text(err);
    query.signal(sig);
    int status = 0;
    ASSERT_TRUE(query.wait(10.0, &status));
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << status;
    EXPECT_FALSE(std::ifstream(log).good()) << log << " left behind";
  }
}

}  // namespace
}  // namespace wrc::bus::test
