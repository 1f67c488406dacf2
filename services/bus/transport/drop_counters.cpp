// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/drop_counters.hpp"

#include <iostream>
#include <mutex>

#include "bus/transport/clock.hpp"

namespace wrc::bus {

namespace {

struct KindLog {
  std::atomic<std::int64_t> count{0};
  double window_start = -1e300;  // [s] monotonic start of the current log window, guarded by the mutex
  int lines_in_window = 0;       // lines logged in it, guarded by the mutex
  std::int64_t not_logged = 0;   // drops not logged since the last line, guarded by the mutex
};

struct DropTally {
  KindLog kinds[kDropKinds];
  std::mutex log_mutex;
};

DropTally& tally() {
  static DropTally* instance = new DropTally;  // never destroyed: drops may come during exit
  return *instance;
}

}  // namespace

const char* drop_kind_name(DropKind kind) {
  switch (kind) {
    case DropKind::kOversize: return "oversize";
    case DropKind::kUnsigned: return "unsigned";
    case DropKind::kBadSignature: return "bad-signature";
    case DropKind::kReplayed: return "replayed";
    case DropKind::kStale: return "stale";
    case DropKind::kWrongType: return "wrong-type";
    case DropKind::kUndecodable: return "undecodable";
    case DropKind::kTrailingBytes: return "trailing-bytes";
    case DropKind::kHandlerFailed: return "handler-failed";
  }
  return "unknown";
}

std::int64_t DropCounts::malformed() const {
  return of(DropKind::kOversize) + of(DropKind::kWrongType) + of(DropKind::kUndecodable) +
         of(DropKind::kTrailingBytes) + of(DropKind::kHandlerFailed);
}

std::int64_t DropCounts::total() const {
  std::int64_t sum = 0;
  for (std::int64_t n : by_kind) sum += n;
  return sum;
}

void record_drop(DropKind kind, const std::string& who, const std::string& channel, const std::string& reason) {
  DropTally& t = tally();
  KindLog& k = t.kinds[static_cast<int>(kind)];
  const std::int64_t count = ++k.count;
  const double now = monotonic_seconds();
  std::lock_guard<std::mutex> lock(t.log_mutex);
  if (now - k.window_start >= kDropLogInterval) {
    k.window_start = now;
    k.lines_in_window = 0;
  }
  if (k.lines_in_window >= kDropLogBurst) {
    ++k.not_logged;
    return;
  }
  ++k.lines_in_window;
  std::cerr << who << ": dropped " << drop_kind_name(kind) << " message on " << channel << ": " << reason << " ("
            << count << " " << drop_kind_name(kind) << " so far";
  if (k.not_logged > 0) std::cerr << ", " << k.not_logged << " not logged since the last line";
  std::cerr << ")\n";
  k.not_logged = 0;
}

DropCounts drop_counts() {
  DropCounts out;
  for (int i = 0; i < kDropKinds; ++i) out.by_kind[i] = tally().kinds[i].count.load();
  return out;
}

}  // namespace wrc::bus
