// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Where the dynamics gets its contact forces from: a batch of configurations in, one result per
/// configuration out. In-process (InProcessContact, for tests and comparison) or over the bus
/// (wrc-dynamicsd's client of a contact service).

#include <memory>
#include <string>
#include <vector>

#include "core/model_interface/contact_model.hpp"

namespace wrc {

/// A source of contact results. Not thread-safe.
class ContactEvaluator {
 public:
  virtual ~ContactEvaluator() = default;
  /// The contact model's name ("onepoint", "interp", "multipoint", "spline").
  virtual std::string model() const = 0;
  /// One result per query, in order, all computed with the same model data.
  /// @throws OutsideModelError / ContactConfigurationError for a configuration the model cannot
  ///         answer (a retry with a smaller step may help); std::runtime_error when the source
  ///         failed (the run cannot go on).
  virtual std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) = 0;
  /// Queries re-sent after a timeout so far [-] (0 in-process).
  virtual long retries() const { return 0; }
  /// Attempt rounds that got no reply so far [-] (0 in-process).
  virtual long timeouts() const { return 0; }
  /// Queries that went to another instance of the model after one got no reply [-] (0 in-process).
  virtual long failovers() const { return 0; }
};

/// A ContactModel called directly.
class InProcessContact final : public ContactEvaluator {
 public:
  explicit InProcessContact(std::shared_ptr<const ContactModel> model);
  std::string model() const override { return model_->name(); }
  std::vector<ContactResult> evaluate(const std::vector<ContactQuery>& batch) override;

 private:
  std::shared_ptr<const ContactModel> model_;
};

}  // namespace wrc
