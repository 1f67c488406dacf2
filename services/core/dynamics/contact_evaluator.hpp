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

/// Where the time of the answered queries of a source over the bus went, summed over them [s],
/// in the order a query goes (the clocks of two hosts differ: across hosts transfer and reply
/// carry the offset between them, with opposite signs).
struct QueryTimes {
  double round_trip = 0;       ///< first send to the reply handled
  double send = 0;             ///< the client's stamping, encoding, signing and send call
  double transfer = 0;         ///< end of the send call to the query's receipt by the service's LCM
  double service_wakeup = 0;   ///< receipt to the service's handler (wake-up, verification, decoding)
  double compute = 0;          ///< the service's evaluation
  double reply = 0;            ///< end of the evaluation to the reply's receipt by the client's LCM
  double client_wakeup = 0;    ///< receipt to the reply handled (wake-up, verification, decoding)
};

/// A source of contact results. Not thread-safe.
class ContactEvaluator {
 public:
  virtual ~ContactEvaluator() = default;
  /// The contact model's name ("onepoint", "interp", "multipoint", "spline").
  virtual std::string model() const = 0;
  /// One result per query, in order, all computed with the same model data. A query whose
  /// ContactQuery::follows is k >= 1 is evaluated with the points answered for query k - 1
  /// (apply_follows(), core/model_interface/followed_points.hpp): every evaluator must honour it.
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
  /// Where the answered queries' time went so far (zeros in-process).
  virtual QueryTimes query_times() const { return {}; }
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
