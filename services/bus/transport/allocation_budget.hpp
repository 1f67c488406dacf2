// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A limit on what one thread may allocate with `new` while a scope is open. LCM's generated C++
/// decoders resize every array to the count the message declares before they read its elements,
/// so a 264-byte message declaring 20 000 000 elements would allocate gigabytes before failing.
/// bus/decode.hpp opens a budget of a small multiple of the message size around each decode: an
/// allocation beyond it throws std::bad_alloc at once, before any memory is touched, and the
/// message is dropped. This works for every message type without knowing its layout.
///
/// The budget is enforced by this library's replacement of the global `operator new` (the
/// standard's replaceable allocation functions); outside a scope it behaves as the standard one.

#include <cstddef>

namespace wrc::bus {

/// While alive, `new` in this thread may allocate at most `bytes` in total; nests (the inner
/// limit applies, the outer one is restored after).
class AllocationBudget {
 public:
  explicit AllocationBudget(std::size_t bytes);
  ~AllocationBudget();
  AllocationBudget(const AllocationBudget&) = delete;
  AllocationBudget& operator=(const AllocationBudget&) = delete;

  /// [B] left of this budget.
  std::size_t remaining() const { return remaining_; }
  /// True when an allocation was refused inside this scope.
  bool exceeded() const { return exceeded_; }

 private:
  friend void* budgeted_allocate(std::size_t size);
  std::size_t remaining_;
  bool exceeded_ = false;
  AllocationBudget* outer_;
};

/// The allocation behind the replaced `operator new`: charges the innermost budget of this
/// thread, if any, and throws std::bad_alloc when it does not cover size.
void* budgeted_allocate(std::size_t size);

}  // namespace wrc::bus
