// SPDX-License-Identifier: Apache-2.0
// What a log line shows of a string from a message (bus/service/log_text.hpp).
#include <gtest/gtest.h>

#include <string>

#include "bus/service/log_text.hpp"

namespace wrc::bus {
namespace {

// Printable ASCII passes unchanged; a newline, an escape sequence, a NUL-free control byte, a
// byte above 0x7f (one of UTF-8's) and the backslash itself (so that "\x0a" typed by a sender
// cannot pass for an escaped newline) are written as escapes.
TEST(LogText, EscapesEveryByteThatIsNotPrintableAscii) {
  EXPECT_EQ(log_text("run-1 (S1002/UIC60)"), "run-1 (S1002/UIC60)");
  EXPECT_EQ(log_text("a\nwrc-dynamicsd: run ended"), "a\\x0awrc-dynamicsd: run ended");
  EXPECT_EQ(log_text("\x1b[2J"), "\\x1b[2J");
  EXPECT_EQ(log_text("\x7f\xc3\xa9"), "\\x7f\\xc3\\xa9");
  EXPECT_EQ(log_text("\\x0a"), "\\\\x0a");
  EXPECT_EQ(log_text(""), "");
}

// A 60 kB string shows as its first kMaxLogText bytes and its length.
TEST(LogText, ALongStringIsCutAndItsLengthNamed) {
  const std::string long_name(60000, 'r');
  const std::string shown = log_text(long_name);
  EXPECT_EQ(shown, std::string(kMaxLogText, 'r') + "... (60000 bytes)");
  EXPECT_EQ(log_text(std::string(kMaxLogText, 'r')), std::string(kMaxLogText, 'r'));
  EXPECT_EQ(log_text("abcdef", 3), "abc... (6 bytes)");
}

}  // namespace
}  // namespace wrc::bus
