// SPDX-License-Identifier: Apache-2.0
// Every contact model refuses configurations outside the range it is valid for (contact_range.hpp):
// an elastic penetration far beyond Hertz (IMPOSSIBLE_CONFIGURATION), a wheelset lifted clear of
// both rails in the elastic formulation (NoContactError, NO_CONTACT on the bus), a rigid gap far
// from contact; and answers, with both wheels' constraints, the configurations the dynamics uses
// (gaps of micrometres, a small lift).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/model_interface/no_contact_error.hpp"
#include "core/models/contact_model_factory.hpp"
#include "core/models/contact_range.hpp"
#include "spline_test_model.hpp"

namespace wrc {
namespace {

// A centred wheelset at height z [m] in the given formulation.
ContactQuery query_at(double z, ContactFormulation formulation) {
  ContactQuery q;
  q.pose.y = 0.001;
  q.pose.z = z;
  q.spin_rate = 30.0 / 0.46;
  q.normal_load = {80e3, 80e3};
  q.formulation = formulation;
  return q;
}

// Height at which the closer wheel just touches [m]: the gaps change one for one with z.
double touching_height(const ContactModel& model) {
  const ContactResult r = model.evaluate(query_at(0.46, ContactFormulation::kRigid));
  return 0.46 - std::min(r.wheels[0].gap, r.wheels[1].gap);
}

// Expects an exception of type E whose message holds every word.
template <typename E>
void expect_refused(const ContactModel& model, const ContactQuery& q, const std::vector<std::string>& words) {
  try {
    model.evaluate(q);
    ADD_FAILURE() << model.name() << " at z = " << q.pose.z << ": no exception";
  } catch (const E& e) {
    for (const std::string& w : words)
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << model.name() << ": '" << w << "' in " << e.what();
  }
}

class ContactRange : public ::testing::TestWithParam<std::string> {
 protected:
  std::shared_ptr<const ContactModel> model() const {
    return make_contact_model(GetParam(), test::s1002_uic60_geometry(), test::small_table_options(), test::quick_spline_data());
  }
};

TEST_P(ContactRange, RigidNearContactAnswersFarGapIsRefused) {
  const auto m = model();
  const double z0 = touching_height(*m);
  for (double dz : {-2e-6, 0.0, 2e-6, 0.015}) {
    const ContactResult r = m->evaluate(query_at(z0 + dz, ContactFormulation::kRigid));
    EXPECT_NEAR(std::min(r.wheels[0].gap, r.wheels[1].gap), dz, 1e-9) << GetParam();
    EXPECT_FALSE(r.patches.empty()) << GetParam();
  }
  for (double dz : {-0.03, 0.03}) {
    const ContactQuery q = query_at(z0 + dz, ContactFormulation::kRigid);
    try {
      m->evaluate(q);
      ADD_FAILURE() << GetParam() << ": rigid gap " << dz << " accepted";
    } catch (const NoContactError& e) {
      ADD_FAILURE() << GetParam() << ": rigid gap is not NO_CONTACT: " << e.what();
    } catch (const ContactConfigurationError& e) {
      EXPECT_NE(std::string(e.what()).find("beyond +-25 mm"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(dz > 0 ? "lifted off" : "sunk into"), std::string::npos) << e.what();
    }
  }
}

TEST_P(ContactRange, ElasticPenetrationBeyondHertzIsImpossible) {
  const auto m = model();
  const double z0 = touching_height(*m);
  const ContactResult ok = m->evaluate(query_at(z0 - 1e-4, ContactFormulation::kElastic));
  ASSERT_FALSE(ok.patches.empty()) << GetParam();
  for (const ContactPatch& p : ok.patches) EXPECT_LT(p.penetration, kMaxElasticPenetration);
  // The example: z = 0.3 m, some 160 mm into the rails.
  expect_refused<ContactConfigurationError>(*m, query_at(0.3, ContactFormulation::kElastic),
                                            {"penetration", "beyond 5 mm", "Hertz", "z = 0.3 m"});
  expect_refused<ContactConfigurationError>(*m, query_at(z0 - 8e-3, ContactFormulation::kElastic),
                                            {"penetration", "beyond 5 mm"});
}

TEST_P(ContactRange, ElasticLiftedWheelsetHasNoContact) {
  const auto m = model();
  const double z0 = touching_height(*m);
  // A lift below a flange height (a bounce): no patches, zero force, both wheels' constraints.
  const ContactResult lifted = m->evaluate(query_at(z0 + 0.02, ContactFormulation::kElastic));
  EXPECT_TRUE(lifted.patches.empty()) << GetParam();
  EXPECT_EQ(lifted.force.norm(), 0.0);
  EXPECT_NEAR(std::min(lifted.wheels[0].gap, lifted.wheels[1].gap), 0.02, 1e-9);
  EXPECT_GT(lifted.wheels[0].normal_z, 0.5);
  EXPECT_GT(lifted.wheels[1].normal_z, 0.5);
  expect_refused<NoContactError>(*m, query_at(z0 + 0.03, ContactFormulation::kElastic),
                                 {"no contact", "lifted", "more than 25 mm"});
}

INSTANTIATE_TEST_SUITE_P(EveryModel, ContactRange, ::testing::ValuesIn(contact_model_names()));

}  // namespace
}  // namespace wrc
