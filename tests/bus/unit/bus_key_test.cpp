// SPDX-License-Identifier: Apache-2.0
// The bus key file: created 0600 in a 0700 directory, read back, refused with a reason when
// missing, open to others, of another length, or not hex; the path's precedence.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "bus/auth/bus_key.hpp"

namespace {
using namespace wrc::bus;
namespace fs = std::filesystem;

class BusKeyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wrc-key-test-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string expect_refused(const std::string& path) {
    try {
      read_bus_key(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    ADD_FAILURE() << "key at " << path << " was accepted";
    return {};
  }
  fs::path dir_;
};

TEST_F(BusKeyFile, CreatedPrivateAndReadBack) {
  const std::string path = (dir_ / "wrc" / "bus.key").string();
  bool created = false;
  const BusKey key = read_or_create_bus_key(path, &created);
  EXPECT_TRUE(created);
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  ASSERT_EQ(::stat((dir_ / "wrc").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0700u);
  EXPECT_EQ(read_bus_key(path).bytes, key.bytes);
  const BusKey again = read_or_create_bus_key(path, &created);
  EXPECT_FALSE(created);
  EXPECT_EQ(again.bytes, key.bytes);
  EXPECT_EQ(fs::file_size(path), 65u);  // 64 hex digits and a newline
}

TEST_F(BusKeyFile, RefusedWithAReason) {
  fs::create_directories(dir_);
  EXPECT_NE(expect_refused((dir_ / "missing.key").string()).find("`wrc launch` creates one"), std::string::npos);
  const std::string path = (dir_ / "bus.key").string();
  read_or_create_bus_key(path);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_NE(expect_refused(path).find("mode 0640 lets group or others at it (chmod 600"), std::string::npos);
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  { std::ofstream(path) << "abc\n"; }
  EXPECT_NE(expect_refused(path).find("expected 64 hex digits, found 3"), std::string::npos);
  { std::ofstream(path) << std::string(63, 'a') << "x\n"; }
  EXPECT_NE(expect_refused(path).find("character 64 is not a hex digit"), std::string::npos);
  EXPECT_NE(expect_refused(dir_.string()).find("not a regular file"), std::string::npos);
}

TEST_F(BusKeyFile, PathPrecedence) {
  ::setenv("WRC_BUS_KEY", "/k/env", 1);
  ::setenv("XDG_CONFIG_HOME", "/k/xdg", 1);
  EXPECT_EQ(bus_key_path("/k/option"), "/k/option");
  EXPECT_EQ(bus_key_path(), "/k/env");
  ::unsetenv("WRC_BUS_KEY");
  EXPECT_EQ(bus_key_path(), "/k/xdg/wrc/bus.key");
  ::unsetenv("XDG_CONFIG_HOME");
  ::setenv("HOME", "/k/home", 1);
  EXPECT_EQ(bus_key_path(), "/k/home/.config/wrc/bus.key");
}

}  // namespace
