#include "cli/centred_run_options.hpp"

#include <iostream>

#include "core/dynamics/run_parameter_table.hpp"
#include "core/dynamics/run_parameters_file.hpp"
#include "options/parameter_options.hpp"

namespace wrc::cli {

RunSpec centred_run_spec(const Options& o, const std::string& why) {
  RunSpec spec;
  if (o.has("--params")) apply_run_parameter_file(o.text("--params"), spec);
  if (o.has("--suspension"))
    spec.wheelset.suspension = o.choice("--suspension", {"benchmark", "none"}) == "none" ? PrimarySuspension::none()
                                                                                         : PrimarySuspension::benchmark();
  const double file_lateral_force = spec.wheelset.lateral_force;
  apply_parameter_options(wheelset_parameter_table(), o, spec.wheelset);
  if (!o.has("--lateral-force") && spec.wheelset.lateral_force != 0.0) {
    std::cout << "lateral load: " << file_lateral_force << " N of the parameters set to 0 (" << why << ")\n";
    spec.wheelset.lateral_force = 0.0;
  }
  return spec;
}

}  // namespace wrc::cli
