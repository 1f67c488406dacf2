// SPDX-License-Identifier: Apache-2.0
#include "cli/centred_run_options.hpp"

#include <iostream>

#include "cli/run_options.hpp"
#include "core/dynamics/run_parameter_table.hpp"
#include "options/parameter_options.hpp"

namespace wrc::cli {

RunSpec centred_run_spec(const Options& o, const std::string& why) {
  RunSpec spec;
  apply_wheelset_sources(o, spec, std::cout);
  apply_parameter_options(wheelset_parameter_table(), o, spec.wheelset);
  zero_lateral_load_unless_given(o, spec.wheelset, why, std::cout);
  return spec;
}

}  // namespace wrc::cli
