// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// The error thrown for bad profile input (files, specifications, point sets).

#include <stdexcept>
#include <string>

namespace wrc {

/// A profile could not be built. what() reads "<source>:<line>: <reason>" (or "<source>: <reason>"
/// when no line applies), so a user sees file, line and reason in one message.
class ProfileError : public std::runtime_error {
 public:
  /// @param source file path or profile specification the error refers to
  /// @param line 1-based line number in the file, 0 if the error is not tied to one line
  /// @param reason what is wrong, in words
  ProfileError(const std::string& source, int line, const std::string& reason);

  /// File path or specification.
  const std::string& source() const { return source_; }
  /// 1-based line number, 0 if none.
  int line() const { return line_; }
  /// The reason without file and line.
  const std::string& reason() const { return reason_; }

 private:
  std::string source_;
  int line_;
  std::string reason_;
};

}  // namespace wrc
