// SPDX-License-Identifier: Apache-2.0
#include "core/dynamics/swap_queue.hpp"

#include <algorithm>

#include "core/numerics/number_text.hpp"

namespace wrc {

std::string swap_failure_message(const std::string& to, double t, const std::string& kept, const std::string& why) {
  return "swap to " + to + " at t = " + exact_number_text(t) + " s failed, keeping " + kept + ": " + why;
}

void SwapQueue::schedule(double t, std::shared_ptr<ContactEvaluator> next) {
  const auto later = std::upper_bound(scheduled_.begin(), scheduled_.end(), t,
                                      [](double time, const Scheduled& s) { return time < s.t; });
  scheduled_.insert(later, Scheduled{t, std::move(next)});
}

std::shared_ptr<ContactEvaluator> SwapQueue::take_due(double t) {
  if (scheduled_.empty() || t < scheduled_.front().t) return nullptr;
  std::shared_ptr<ContactEvaluator> next = std::move(scheduled_.front().next);
  scheduled_.pop_front();
  return next;
}

}  // namespace wrc
