#include "contactd/instance_filter.hpp"

#include "bus/transport/clock.hpp"

namespace wrc::contactd {

bool InstanceFilter::is_leader() const {
  for (const auto& s : monitor_.services(bus::monotonic_seconds())) {
    if (s.last.model == model_ && s.available() && s.last.instance < instance_) return false;
  }
  return true;
}

bool InstanceFilter::answers(const wrc::contact_query_t& query) const {
  if (!query.instance.empty()) return query.instance == instance_;
  return is_leader();
}

}  // namespace wrc::contactd
