// SPDX-License-Identifier: Apache-2.0
// The one profile file rule (services/core/profile/profile_file_bytes.hpp) on every path that reads
// a profile file: the readers and the geometry key's content hash, which every request, model and
// run command computes before a profile is loaded. Before this rule the content hash read with an
// unbounded istreambuf: /dev/zero read until std::bad_alloc without naming the file, a FIFO without
// a writer blocked its caller (a service) until it was killed.

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "core/identity/geometry_key.hpp"
#include "core/profile/profile_error.hpp"
#include "core/profile/profile_file_bytes.hpp"
#include "core/profile/profile_limits.hpp"

namespace wrc {
namespace {

namespace fs = std::filesystem;

class ProfileFileBytes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wrc_profile_bytes_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The message of the ProfileError that f throws; fails the test when f throws nothing or
// something else.
template <class F>
std::string profile_error_of(F f) {
  try {
    f();
  } catch (const ProfileError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ProfileError: " << e.what();
    return "";
  }
  ADD_FAILURE() << "nothing thrown";
  return "";
}

TEST_F(ProfileFileBytes, ReadsARegularFileExactly) {
  const std::string path = (dir_ / "wheel.txt").string();
  const std::string text = std::string("0 0\n1 0.5\r\n\0binary", 19) + std::string(100000, 'x');
  std::ofstream(path, std::ios::binary) << text;
  EXPECT_EQ(read_profile_file_bytes(path), text);
}

// Devices, FIFOs and directories are refused at once, by the readers and by the content hash, with
// the file named; the limit is the same for both. A FIFO without a writer would block open(2)
// without O_NONBLOCK, and /dev/zero never ends: either would hang this test until CTest's
// timeout stops it. The time taken is printed, not asserted.
TEST_F(ProfileFileBytes, SpecialFilesAreRefusedAtOnceOnEveryPath) {
  const std::string fifo = (dir_ / "wheel.fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto t0 = std::chrono::steady_clock::now();
  const struct {
    std::string path;
    const char* kind;
  } cases[] = {{"/dev/zero", "a character device"},
               {"/dev/urandom", "a character device"},
               {fifo, "a FIFO"},
               {dir_.string(), "a directory"}};
  for (const auto& c : cases) {
    const std::string expected = c.path + ": not a regular file (" + c.kind + ")";
    EXPECT_EQ(profile_error_of([&] { read_profile_file_bytes(c.path); }), expected);
    EXPECT_EQ(profile_error_of([&] { profile_content_hash(c.path); }), expected);
    GeometrySpec spec;
    spec.wheel = c.path;
    EXPECT_EQ(profile_error_of([&] { geometry_key(spec); }), expected);
  }
  std::cout << "[ measured ] refusing " << std::size(cases) << " special files on 3 paths: "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
}

TEST_F(ProfileFileBytes, MissingAndOversizedFilesAreNamed) {
  const std::string missing = (dir_ / "missing.txt").string();
  EXPECT_EQ(profile_error_of([&] { profile_content_hash(missing); }),
            missing + ": cannot open file (No such file or directory)");
  const std::string huge = (dir_ / "huge.txt").string();
  {
    std::ofstream out(huge, std::ios::binary);
    out << std::string(kMaxProfileFileBytes + 1, '#');
  }
  const std::string expected = huge + ": file too large: " + std::to_string(kMaxProfileFileBytes + 1) +
                               " bytes (at most " + std::to_string(kMaxProfileFileBytes) + ")";
  EXPECT_EQ(profile_error_of([&] { read_profile_file_bytes(huge); }), expected);
  EXPECT_EQ(profile_error_of([&] { profile_content_hash(huge); }), expected);
  // At the limit the file is read.
  fs::resize_file(huge, kMaxProfileFileBytes);
  EXPECT_EQ(read_profile_file_bytes(huge).size(), kMaxProfileFileBytes);
}

}  // namespace
}  // namespace wrc
