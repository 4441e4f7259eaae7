// Checkpoints: a round trip keeps every bit (state, derivatives, counters, nested arrays),
// a rewrite replaces the file atomically (no temporary left, the old one intact when the new
// one cannot be written), bad files are InputErrors naming the file, and the settings hash is
// stable (FNV-1a 64 reference values).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"

namespace rfmems {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("rfmems_checkpoint_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

Checkpoint sample() {
  Checkpoint cp;
  cp.time = 1234567.891011;
  for (int k = 0; k < 100; ++k) {
    cp.state.push_back(std::sin(k + 0.1) * std::pow(10.0, -k % 17));
    cp.state_dot.push_back(std::nextafter(1.0 / (k + 3), 2.0));
  }
  cp.state.push_back(std::numeric_limits<double>::denorm_min());
  cp.state_dot.push_back(-0.0);
  cp.settings_hash = settings_hash("case: text");
  cp.numbers = {{"steps", 4711}, {"next_output", 7}, {"wall_time_s", 0.125}};
  cp.arrays["series"] = {0, 1, 2, 3.5, -4};
  cp.arrays["outputs/000003/structure"] = {1e-9, -2e-9};
  cp.arrays["empty"] = {};
  return cp;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(Checkpoint, RoundTripKeepsEveryBit) {
  const std::string path = scratch("round_trip.h5").string();
  const Checkpoint cp = sample();
  write_checkpoint(path, cp);
  const Checkpoint back = read_checkpoint(path);
  EXPECT_EQ(back.time, cp.time);
  EXPECT_TRUE(same_bits(back.state, cp.state));
  EXPECT_TRUE(same_bits(back.state_dot, cp.state_dot));
  EXPECT_TRUE(std::signbit(back.state_dot.back()));
  EXPECT_EQ(back.settings_hash, cp.settings_hash);
  EXPECT_EQ(back.numbers, cp.numbers);
  ASSERT_EQ(back.arrays.size(), cp.arrays.size());
  for (const auto& [name, values] : cp.arrays) {
    ASSERT_TRUE(back.arrays.count(name)) << name;
    EXPECT_TRUE(same_bits(back.arrays.at(name), values)) << name;
  }
  EXPECT_FALSE(fs::exists(temp_path_for(path)));
}

TEST(Checkpoint, RewriteReplacesAtomically) {
  const std::string path = scratch("rewrite.h5").string();
  Checkpoint cp = sample();
  write_checkpoint(path, cp);
  cp.time = 2;
  cp.state.assign(3, 1.5);
  cp.state_dot.assign(3, -1.5);
  write_checkpoint(path, cp);
  const Checkpoint back = read_checkpoint(path);
  EXPECT_EQ(back.time, 2);
  EXPECT_EQ(back.state, cp.state);
  EXPECT_FALSE(fs::exists(temp_path_for(path)));

  // A write that fails half-way leaves the previous checkpoint intact: "a" is written as a
  // dataset first, then "a/b" needs "a" as a group.
  Checkpoint bad = cp;
  bad.time = 3;
  bad.arrays["a"] = {1};
  bad.arrays["a/b"] = {1};
  EXPECT_THROW(write_checkpoint(path, bad), std::runtime_error);
  EXPECT_EQ(read_checkpoint(path).time, 2);
  EXPECT_FALSE(fs::exists(temp_path_for(path)));
}

TEST(Checkpoint, BadFilesAreInputErrorsNamingTheFile) {
  const std::string missing = scratch("missing.h5").string();
  try {
    read_checkpoint(missing);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  const std::string text = scratch("text.h5").string();
  std::ofstream(text) << "not hdf5\n";
  EXPECT_THROW(read_checkpoint(text), InputError);
  // A truncated checkpoint (what a non-atomic writer would leave after SIGKILL).
  const std::string good = scratch("good.h5").string(), cut = scratch("cut.h5").string();
  write_checkpoint(good, sample());
  fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(good) / 2);
  EXPECT_THROW(read_checkpoint(cut), InputError);
}

TEST(Checkpoint, SettingsHashIsFnv1a64) {
  // Reference values of FNV-1a 64.
  EXPECT_EQ(settings_hash(""), "cbf29ce484222325");
  EXPECT_EQ(settings_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(settings_hash("foobar"), "85944171f73967e8");
  EXPECT_NE(settings_hash("rtol: 1e-6"), settings_hash("rtol: 1e-7"));
}

}  // namespace
}  // namespace rfmems
