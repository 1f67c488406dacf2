// SPDX-License-Identifier: Apache-2.0
#include "protocol/run/run_request_table.hpp"

#include "core/dynamics/run_parameter_table.hpp"

namespace wrc::protocol {

const std::vector<Parameter<RunRequest>>& contact_client_table() {
  using R = RunRequest;
  static const std::vector<Parameter<R>> table{
      // At least 1 ms, as `wrc query --timeout`: below a bus round trip no reply can come in time,
      // and a run would only re-send its query until contact_wait ends.
      member_parameter<R>({"contact_timeout", "--timeout", "s", "contact query timeout per attempt",
                           ParameterKind::kNumber, closed(1e-3, 60.0)}, &R::contact_timeout),
      member_parameter<R>({"contact_retries", "--retries", "-", "contact query re-sends per round",
                           ParameterKind::kInteger, closed(0, 100)}, &R::contact_retries),
      member_parameter<R>({"contact_wait", nullptr, "s", "longest wait for a (restarted) contact service",
                           ParameterKind::kNumber, closed(0.0, 3600.0)}, &R::contact_wait),
  };
  return table;
}

const std::vector<Parameter<RunRequest>>& run_request_table() {
  static const std::vector<Parameter<RunRequest>> table = [] {
    std::vector<Parameter<RunRequest>> t = lift_parameters(run_parameter_table(), &RunRequest::spec);
    t.insert(t.end(), contact_client_table().begin(), contact_client_table().end());
    return t;
  }();
  return table;
}

}  // namespace wrc::protocol
