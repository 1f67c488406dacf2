// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Clean shutdown on SIGINT/SIGTERM: the handler only sets a flag; the service loop sees it
/// within one loop period, publishes a DRAINING heartbeat and returns.

namespace wrc::bus {

/// Process-wide shutdown flag set by SIGINT and SIGTERM.
class ShutdownSignal {
 public:
  /// Installs the handlers for SIGINT and SIGTERM (without SA_RESTART, so a blocking wait
  /// returns early). Safe to call more than once.
  static void install();
  /// True once SIGINT or SIGTERM arrived (or request() was called).
  static bool requested();
  /// The signal that asked for shutdown (0 = none or request()).
  static int signal_number();
  /// Asks for shutdown from inside the process (tests, fatal errors).
  static void request();
  /// Clears the flag (tests only).
  static void reset();
};

}  // namespace wrc::bus
