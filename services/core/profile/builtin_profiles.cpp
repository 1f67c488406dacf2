// SPDX-License-Identifier: Apache-2.0
#include "core/profile/builtin_profiles.hpp"

#include <memory>

#include "core/profile/s1002.hpp"
#include "core/profile/uic60.hpp"

namespace wrc {

const std::array<BuiltinProfile, 3> kBuiltinProfiles{{
    {"S1002", ProfileSide::kWheel, [] { return ProfilePtr(std::make_shared<S1002Profile>()); }},
    {"UIC60", ProfileSide::kRail, [] { return ProfilePtr(std::make_shared<Uic60Profile>(Uic60Variant::kEn60E1)); }},
    {"UIC60-MB", ProfileSide::kRail,
     [] { return ProfilePtr(std::make_shared<Uic60Profile>(Uic60Variant::kManchester)); }},
}};

const BuiltinProfile* find_builtin_profile(const std::string& spec) {
  for (const BuiltinProfile& p : kBuiltinProfiles)
    if (spec == p.name) return &p;
  return nullptr;
}

}  // namespace wrc
