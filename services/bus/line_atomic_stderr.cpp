#include "bus/line_atomic_stderr.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <streambuf>
#include <string>

namespace wrc::bus {
namespace {

constexpr std::size_t kMaxLine = 4096;  // PIPE_BUF on Linux: writes up to this size are atomic

void write_all(const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(STDERR_FILENO, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return;  // nowhere left to report a failing stderr
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

// Each thread collects its own line (so that threads writing at once do not mix their pieces)
// and hands it to the kernel in one write(2).
class LineAtomicBuffer : public std::streambuf {
 public:
  static void flush_partial() { emit(); }

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

  int sync() override { return 0; }  // complete lines are out already; a partial one waits for '\n'

 private:
  static std::string& line() {
    thread_local std::string pending;
    return pending;
  }
  static void append(const char* s, std::size_t n) {
    std::string& pending = line();
    for (std::size_t i = 0; i < n; ++i) {
      pending.push_back(s[i]);
      if (s[i] == '\n' || pending.size() >= kMaxLine) emit();
    }
  }
  static void emit() {
    std::string& pending = line();
    write_all(pending.data(), pending.size());
    pending.clear();
  }
};

LineAtomicBuffer* installed = nullptr;

}  // namespace

void make_stderr_line_atomic() {
  if (installed != nullptr) return;
  installed = new LineAtomicBuffer;  // never destroyed: std::cerr may be used until the very end
  std::cerr.rdbuf(installed);
  std::atexit([] { LineAtomicBuffer::flush_partial(); });
}

}  // namespace wrc::bus
