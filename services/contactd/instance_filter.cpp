// SPDX-License-Identifier: Apache-2.0
#include "contactd/instance_filter.hpp"

#include "bus/transport/clock.hpp"

namespace wrc::contactd {

bool InstanceFilter::is_leader() const {
  return !monitor_.available_before(model_, instance_, bus::monotonic_seconds());
}

bool InstanceFilter::answers(const wrc::contact_query_t& query) const {
  if (!query.instance.empty()) return query.instance == instance_;
  return is_leader();
}

}  // namespace wrc::contactd
