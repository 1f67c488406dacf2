// SPDX-License-Identifier: Apache-2.0
#include "dynamicsd/run_end_log.hpp"

#include <sstream>

#include "bus/service/log_text.hpp"

namespace wrc::dynamics {

std::string run_end_log_line(const std::string& run_id, double t, const std::string& reason, double wall_time,
                             const RunCounters& counters) {
  std::ostringstream out;
  out << "wrc-dynamicsd: run " << bus::log_text(run_id) << " ended at t = " << t << " s";
  if (!reason.empty()) out << " (" << bus::log_text(reason) << ")";
  out << " in " << wall_time << " s, " << counters.steps << " steps, " << counters.restarts << " restarts, "
      << counters.contact_queries << " contact queries";
  return out.str();
}

}  // namespace wrc::dynamics
