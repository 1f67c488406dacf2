// SPDX-License-Identifier: Apache-2.0
// Identities: SHA-256 against the FIPS 180-2 test vectors; the geometry key changes with every
// field of the geometry input (each profile by its content) and not with the path a file is
// reached by; geometry_arguments names every field.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/identity/geometry_key.hpp"
#include "core/identity/sha256.hpp"
#include "core/profile/profile_error.hpp"

namespace wrc {
namespace {

namespace fs = std::filesystem;

bool is_sha256_hex(const std::string& s) {
  return s.size() == 64 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// A private folder with a copy of a rail and a wheel profile file, removed afterwards.
class GeometryKeyFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wrc-identity-test-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "sub");
    fs::copy_file(fs::path(WRC_PROFILES_DIR) / "MBench_UIC60_v3.prr", rail(), fs::copy_options::overwrite_existing);
    fs::copy_file(fs::path(WRC_PROFILES_DIR) / "MBench_S1002_v3.prw", wheel(), fs::copy_options::overwrite_existing);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string rail() const { return (dir_ / "rail.prr").string(); }
  std::string wheel() const { return (dir_ / "wheel.prw").string(); }
  static void append(const std::string& file, const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::app) << text;
  }
  fs::path dir_;
};

// ---- SHA-256 ---------------------------------------------------------------------------------

TEST(Sha256, Fips180TestVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, BytesAndStringAgreeIncludingZeroBytes) {
  const unsigned char bytes[] = {'a', 0, 'b', 0xff, 0};
  const std::string text(reinterpret_cast<const char*>(bytes), sizeof bytes);
  EXPECT_EQ(sha256_hex(bytes, sizeof bytes), sha256_hex(text));
  EXPECT_NE(sha256_hex(bytes, sizeof bytes), sha256_hex(bytes, sizeof bytes - 1));
  EXPECT_EQ(sha256_hex(nullptr, 0), sha256_hex(""));
  EXPECT_TRUE(is_sha256_hex(sha256_hex(bytes, sizeof bytes)));
}

// Model data hashes: each double as its 8 bits' bytes, least significant first, whatever the
// host's byte order (1.0 = 0x3ff0000000000000, -2.5 = 0xc004000000000000).
TEST(Sha256, DoublesAreHashedAsLittleEndianBytes) {
  const unsigned char bytes[] = {0, 0, 0, 0, 0, 0, 0xf0, 0x3f, 0, 0, 0, 0, 0, 0, 0x04, 0xc0};
  EXPECT_EQ(sha256_hex_of_doubles({1.0, -2.5}), sha256_hex(bytes, sizeof bytes));
  EXPECT_EQ(sha256_hex_of_doubles({}), sha256_hex(""));
  EXPECT_NE(sha256_hex_of_doubles({0.0}), sha256_hex_of_doubles({-0.0}));  // bits, not values
}

// ---- geometry key ----------------------------------------------------------------------------

TEST(GeometryKey, IsTheSha256OfTheVersionedCanonicalText) {
  const GeometrySpec spec;
  const std::string text = geometry_key_text(spec);
  EXPECT_EQ(text.rfind(std::string(kGeometryKeyVersion) + "\n", 0), 0u) << text;
  EXPECT_NE(text.find("wheel builtin S1002\n"), std::string::npos) << text;
  EXPECT_NE(text.find("rail builtin UIC60\n"), std::string::npos) << text;
  EXPECT_NE(text.find("rail_cant profile\n"), std::string::npos) << text;
  EXPECT_NE(text.find("gauge 1.4350000000000001\n"), std::string::npos) << text;  // %.17g
  EXPECT_NE(text.find("taping_line_offset 0.070000000000000007\n"), std::string::npos) << text;
  EXPECT_EQ(geometry_key(spec), sha256_hex(text));
  EXPECT_TRUE(is_sha256_hex(geometry_key(spec)));
  EXPECT_EQ(geometry_key(spec), geometry_key(GeometrySpec{}));
}

// Each single change of any field gives a new key, and no two of the changed specs share one.
TEST_F(GeometryKeyFiles, KeyChangesWithEverySingleField) {
  GeometrySpec base;
  base.wheel = wheel();
  base.rail = rail();
  const std::vector<std::pair<std::string, std::function<void(GeometrySpec&)>>> changes{
      {"wheel built-in", [](GeometrySpec& s) { s.wheel = "S1002"; }},
      {"wheel cone", [](GeometrySpec& s) { s.wheel = "conic:0.025"; }},
      {"rail built-in", [](GeometrySpec& s) { s.rail = "UIC60"; }},
      {"rail Manchester variant", [](GeometrySpec& s) { s.rail = "UIC60-MB"; }},
      {"rail circle", [](GeometrySpec& s) { s.rail = "circle:0.3"; }},
      {"rail cant given", [](GeometrySpec& s) { s.rail_cant = std::atan(1.0 / 40.0); }},
      {"rail cant 0", [](GeometrySpec& s) { s.rail_cant = 0.0; }},
      {"gauge", [](GeometrySpec& s) { s.track.gauge += 1e-9; }},
      {"gauge_depth", [](GeometrySpec& s) { s.track.gauge_depth = 0.016; }},
      {"flange_back_spacing", [](GeometrySpec& s) { s.track.flange_back_spacing += 1e-9; }},
      {"taping_line_offset", [](GeometrySpec& s) { s.track.taping_line_offset = 0.0705; }},
      {"inclination", [](GeometrySpec& s) { s.track.inclination = std::atan(1.0 / 20.0); }},
      {"nominal_radius", [](GeometrySpec& s) { s.track.nominal_radius = 0.45; }},
      {"last bit of the gauge", [](GeometrySpec& s) { s.track.gauge = std::nextafter(s.track.gauge, 2.0); }},
  };
  const std::string base_key = geometry_key(base);
  std::set<std::string> keys{base_key};
  for (const auto& [what, change] : changes) {
    GeometrySpec spec = base;
    change(spec);
    const std::string key = geometry_key(spec);
    EXPECT_TRUE(is_sha256_hex(key)) << what << ": " << key;
    EXPECT_NE(key, base_key) << what;
    EXPECT_TRUE(keys.insert(key).second) << what << " gives the key of another change";
  }
  // A profile file's content: one byte more in either file, same paths.
  append(rail(), " ");
  const std::string edited_rail = geometry_key(base);
  EXPECT_NE(edited_rail, base_key);
  append(wheel(), "\n");
  EXPECT_NE(geometry_key(base), edited_rail);
  EXPECT_NE(geometry_key(base), base_key);
}

// A file is its content: another path to the same bytes (relative, with "..", a symlink, a
// copy) gives the same key; the wheel and rail fields stay apart.
TEST_F(GeometryKeyFiles, KeyDoesNotDependOnThePathOfAFile) {
  GeometrySpec spec;
  spec.rail = rail();
  const std::string key = geometry_key(spec);
  const std::vector<std::string> same_file{
      (dir_ / "sub" / ".." / "rail.prr").string(), (dir_ / "." / "rail.prr").string(),
      fs::relative(rail(), fs::current_path()).string()};
  fs::create_symlink(rail(), dir_ / "link.prr");
  fs::copy_file(rail(), dir_ / "sub" / "copy.prr");
  for (const std::string& path : same_file) {
    GeometrySpec other = spec;
    other.rail = path;
    EXPECT_EQ(geometry_key(other), key) << path;
  }
  for (const char* name : {"link.prr", "sub/copy.prr"}) {
    GeometrySpec other = spec;
    other.rail = (dir_ / name).string();
    EXPECT_EQ(geometry_key(other), key) << name;
  }
  // The same bytes as the wheel instead of the rail is another geometry.
  GeometrySpec swapped;
  swapped.wheel = rail();
  swapped.rail = rail();
  EXPECT_NE(geometry_key(swapped), key);
}

TEST(GeometryKey, BuiltInParametersAreCanonical) {
  GeometrySpec a, b;
  a.wheel = "conic:0.05";
  b.wheel = "conic:5e-2";
  EXPECT_EQ(geometry_key(a), geometry_key(b));
  a.rail = "circle:0.3";
  b.rail = "circle:0.30";
  EXPECT_EQ(geometry_key(a), geometry_key(b));
}

TEST(GeometryKey, UnreadableFileIsAProfileError) {
  GeometrySpec spec;
  spec.rail = "no-such-profile-file.prr";
  EXPECT_THROW(geometry_key(spec), ProfileError);
}

// ---- geometry arguments ----------------------------------------------------------------------

TEST(GeometryArguments, NameEveryField) {
  GeometrySpec spec;
  std::vector<std::string> args = geometry_arguments(spec);
  auto value_of = [&](const std::string& option) -> std::string {
    const auto it = std::find(args.begin(), args.end(), option);
    return it == args.end() || it + 1 == args.end() ? "(absent)" : *(it + 1);
  };
  EXPECT_EQ(value_of("--wheel"), "S1002");
  EXPECT_EQ(value_of("--rail"), "UIC60");
  EXPECT_EQ(value_of("--rail-cant"), "(absent)");  // unset: the profile's own
  EXPECT_EQ(std::stod(value_of("--gauge")), spec.track.gauge);
  EXPECT_EQ(std::stod(value_of("--gauge-depth")), spec.track.gauge_depth);
  EXPECT_EQ(std::stod(value_of("--flange-back")), spec.track.flange_back_spacing);
  EXPECT_EQ(std::stod(value_of("--taping-line-offset")), spec.track.taping_line_offset);
  EXPECT_EQ(std::stod(value_of("--inclination")), spec.track.inclination);  // 17 digits: exact
  EXPECT_EQ(std::stod(value_of("--r0")), spec.track.nominal_radius);
  spec.rail_cant = std::atan(1.0 / 40.0);
  args = geometry_arguments(spec);
  EXPECT_EQ(std::stod(value_of("--rail-cant")), *spec.rail_cant);
}

}  // namespace
}  // namespace wrc
