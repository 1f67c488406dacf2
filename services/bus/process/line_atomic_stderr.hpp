// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Whole-line writes to standard error. The launcher gives all services one log; a line that a
/// process writes in pieces (every `<<` of an unbuffered std::cerr is a write(2) of its own) can be
/// cut by another process's line. With std::cerr line-atomic, each line reaches the log with one
/// write(2), which the kernel does not interleave with other writes to a pipe (up to 4096 bytes)
/// or to a file opened for appending.

namespace wrc::bus {

/// Routes std::cerr through a line buffer from now on: each thread's text is collected until '\n'
/// and the line is written with one write(2) to file descriptor 2; a line longer than 4096 bytes
/// is written as soon as it reaches that size. Call it from main before other threads start; a
/// second call changes nothing. The buffers stay usable until the process ends, so that output
/// from atexit handlers and static destructors still arrives; an unfinished line is written when
/// its thread ends or, for the main thread, at exit. std::cerr.flush() does not write an
/// unfinished line, and nothing pending survives std::_Exit or a crash: end messages with '\n'.
void make_stderr_line_atomic();

}  // namespace wrc::bus
