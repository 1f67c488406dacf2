#include "core/models/contact_model_factory.hpp"

#include <stdexcept>

#include "core/models/interpolated_model.hpp"
#include "core/models/multi_point_model.hpp"
#include "core/models/one_point_model.hpp"

namespace wrc {

std::vector<std::string> contact_model_names() { return {"onepoint", "interp", "multipoint"}; }

std::unique_ptr<ContactModel> make_contact_model(const std::string& name,
                                                 std::shared_ptr<const WheelsetGeometry> geometry,
                                                 const ContactModelOptions& options) {
  if (name == "onepoint") return std::make_unique<OnePointModel>(std::move(geometry), options);
  if (name == "interp") return std::make_unique<InterpolatedModel>(std::move(geometry), options);
  if (name == "multipoint") return std::make_unique<MultiPointModel>(std::move(geometry), options);
  if (name == "spline")
    throw std::invalid_argument(
        "contact model 'spline' (Arnold's spline approximation) is not available yet; known models: onepoint, "
        "interp, multipoint");
  std::string known;
  for (const std::string& n : contact_model_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown contact model '" + name + "'; known models: " + known);
}

}  // namespace wrc
