// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A test helper: fn() must throw std::invalid_argument whose message contains a given text.

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>

namespace wrc::test {

/// Expects fn() to throw std::invalid_argument whose message contains `text`.
template <class F>
void expect_invalid(F fn, const std::string& text) {
  try {
    fn();
    ADD_FAILURE() << "no exception, expected one mentioning '" << text << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

/// Expects fn() to throw std::invalid_argument whose message contains every one of texts.
template <class F>
void expect_invalid(F fn, std::initializer_list<const char*> texts) {
  try {
    fn();
    ADD_FAILURE() << "no exception, expected one mentioning '" << *texts.begin() << "'";
  } catch (const std::invalid_argument& e) {
    for (const char* text : texts) EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

}  // namespace wrc::test
