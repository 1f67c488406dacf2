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
/// second call changes nothing. The buffer is never destroyed, so that output during static
/// destruction still arrives; the main thread's unfinished last line is written at exit.
void make_stderr_line_atomic();

}  // namespace wrc::bus
