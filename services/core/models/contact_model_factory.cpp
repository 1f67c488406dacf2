// SPDX-License-Identifier: Apache-2.0
#include "core/models/contact_model_factory.hpp"

#include <stdexcept>

#include "core/models/interpolated_model.hpp"
#include "core/models/multi_point_model.hpp"
#include "core/models/one_point_model.hpp"
#include "core/models/spline_model.hpp"

namespace wrc {
namespace {

template <typename Model>
ContactModelEntry plain(std::string name, std::string description, ContactFormulation formulation) {
  ContactModelEntry entry;
  entry.name = std::move(name);
  entry.description = std::move(description);
  entry.dynamics_formulation = formulation;
  entry.build = [](std::shared_ptr<const WheelsetGeometry> g, const ContactModelOptions& o, const ContactModelData&) {
    return std::unique_ptr<ContactModel>(std::make_unique<Model>(std::move(g), o));
  };
  return entry;
}

ContactModelEntry spline_entry() {
  ContactModelEntry entry;
  entry.name = "spline";
  entry.description = "Arnold's unified approach: weighted least-squares tensor-product splines";
  entry.needs_data = true;
  entry.dynamics_formulation = ContactFormulation::kRigid;
  entry.build = [](std::shared_ptr<const WheelsetGeometry> g, const ContactModelOptions& o, const ContactModelData& d) {
    if (!d.splines)
      throw std::invalid_argument(
          "contact model 'spline' needs a fitted spline model (precomputed by wrc-geometryd or `wrc fit`)");
    return std::unique_ptr<ContactModel>(std::make_unique<SplineModel>(std::move(g), d.splines, o));
  };
  return entry;
}

}  // namespace

const std::vector<ContactModelEntry>& contact_model_registry() {
  static const std::vector<ContactModelEntry> registry{
      plain<OnePointModel>("onepoint", "Hertzian one-point contact at the exact common point",
                           ContactFormulation::kRigid),
      plain<InterpolatedModel>("interp", "interpolated Hertzian contact (MEDYNA): a table of common points",
                               ContactFormulation::kRigid),
      plain<MultiPointModel>("multipoint", "Hertzian multi-point contact: an ellipse at every local minimum",
                             ContactFormulation::kElastic),
      spline_entry(),
  };
  return registry;
}

std::vector<std::string> contact_model_names() {
  std::vector<std::string> names;
  for (const ContactModelEntry& e : contact_model_registry()) names.push_back(e.name);
  return names;
}

const ContactModelEntry& contact_model_entry(const std::string& name) {
  for (const ContactModelEntry& e : contact_model_registry())
    if (e.name == name) return e;
  std::string known;
  for (const std::string& n : contact_model_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown contact model '" + name + "'; known models: " + known);
}

std::unique_ptr<ContactModel> make_contact_model(const std::string& name,
                                                 std::shared_ptr<const WheelsetGeometry> geometry,
                                                 const ContactModelOptions& options, const ContactModelData& data) {
  return contact_model_entry(name).build(std::move(geometry), options, data);
}

}  // namespace wrc
