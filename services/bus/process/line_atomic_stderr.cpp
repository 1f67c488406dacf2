// SPDX-License-Identifier: Apache-2.0
#include "bus/process/line_atomic_stderr.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <streambuf>

namespace wrc::bus {
namespace {

constexpr std::size_t kMaxLine = 4096;  // PIPE_BUF on Linux: writes up to this size are atomic

void write_all(const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(STDERR_FILENO, data, size);
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;  // EAGAIN: a non-blocking stderr that is full
      return;  // nowhere left to report a failing stderr
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

// Each thread's unfinished line. Trivially destructible, so that it stays usable while the
// process exits (atexit handlers and static destructors run after the thread's objects with
// destructors are gone).
struct PendingLine {
  char text[kMaxLine];
  std::size_t size;
};
thread_local PendingLine pending_line{};

void emit() {
  write_all(pending_line.text, pending_line.size);
  pending_line.size = 0;
}

// Writes what a thread leaves unfinished when it ends (the main thread's rest is written at exit).
struct FlushAtThreadEnd {
  ~FlushAtThreadEnd() { emit(); }
};

void append(const char* s, std::size_t n) {
  thread_local FlushAtThreadEnd flush_at_thread_end;
  (void)flush_at_thread_end;
  for (std::size_t i = 0; i < n; ++i) {
    pending_line.text[pending_line.size++] = s[i];
    if (s[i] == '\n' || pending_line.size == kMaxLine) emit();
  }
}

// Each thread collects its own line (so that threads writing at once do not mix their pieces)
// and hands it to the kernel in one write(2).
class LineAtomicBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type ch) override {
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    const char c = traits_type::to_char_type(ch);
    append(&c, 1);
    return ch;
  }

  std::streamsize xsputn(const char* s, std::streamsize n) override {
    append(s, static_cast<std::size_t>(n));
    return n;
  }

  // Complete lines are out already; an unfinished one waits for its '\n' (or the thread's end).
  int sync() override { return 0; }
};

LineAtomicBuffer* installed = nullptr;

}  // namespace

void make_stderr_line_atomic() {
  if (installed != nullptr) return;
  installed = new LineAtomicBuffer;  // never destroyed: std::cerr may be used until the very end
  std::cerr.rdbuf(installed);
  std::atexit([] { emit(); });
}

}  // namespace wrc::bus
