// SPDX-License-Identifier: Apache-2.0
#include "core/model_interface/followed_points.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wrc {

void follow_answered_points(const ContactResult& answered, std::array<double, 2>& tracked,
                            std::array<double, 2>& second_tracked) {
  for (size_t w = 0; w < 2; ++w) {
    tracked[w] = answered.wheels[w].s_wheel;
    if (!std::isnan(second_tracked[w]) && answered.second_wheels[w]) second_tracked[w] = answered.second_wheels[w]->s_wheel;
  }
}

void apply_follows(const std::vector<const ContactResult*>& answered, int index, ContactQuery& query) {
  if (query.follows == 0) return;
  const std::string where = "configuration " + std::to_string(index) + ": follows " + std::to_string(query.follows);
  if (query.follows < 0 || query.follows > index)
    throw std::invalid_argument(where + " is not 0 or the number of an earlier configuration plus 1 (1.." +
                                std::to_string(index) + ")");
  const ContactResult* followed = answered.at(static_cast<size_t>(query.follows - 1));
  if (followed == nullptr)
    throw std::invalid_argument(where + ": configuration " + std::to_string(query.follows - 1) + " has no answer");
  follow_answered_points(*followed, query.tracked_s_wheel, query.second_tracked_s_wheel);
}

}  // namespace wrc
