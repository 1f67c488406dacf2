// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The model swaps a run has been asked for and not made yet: a live one (`wrc swap`, made at the
/// next step boundary) and scheduled ones (`--swap-at`, each made at the first step boundary at or
/// after its time). One place for the lone wheelset's run and a vehicle's.

#include <deque>
#include <memory>
#include <string>
#include <utility>

#include "core/dynamics/contact_evaluator.hpp"

namespace wrc {

/// What a run says when a swap to model `to` at time t [s] failed and it keeps model `kept`: why.
std::string swap_failure_message(const std::string& to, double t, const std::string& kept, const std::string& why);

class SwapQueue {
 public:
  /// A live swap to next, replacing one not made yet.
  void request(std::shared_ptr<ContactEvaluator> next) { pending_ = std::move(next); }
  /// A swap to next at time t [s]; swaps of equal times keep the order they were scheduled in.
  void schedule(double t, std::shared_ptr<ContactEvaluator> next);
  /// The live swap, taken out; null when none.
  std::shared_ptr<ContactEvaluator> take_requested() { return std::exchange(pending_, nullptr); }
  /// The earliest scheduled swap due at time t [s] (its time <= t), taken out; null when none.
  std::shared_ptr<ContactEvaluator> take_due(double t);

 private:
  struct Scheduled {
    double t = 0;  // [s]
    std::shared_ptr<ContactEvaluator> next;
  };
  std::shared_ptr<ContactEvaluator> pending_;
  std::deque<Scheduled> scheduled_;  // in the order of their times
};

}  // namespace wrc
