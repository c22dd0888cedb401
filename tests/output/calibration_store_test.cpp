// Stencil calibrations on disk (output/calibration_store.hpp): a calibration is read back only for
// exactly the inputs it was measured on, and a damaged or foreign file is measured again.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "membra/io/design_reader.hpp"
#include "membra/output/calibration_store.hpp"

namespace membra {
namespace {
namespace fs = std::filesystem;

nlohmann::json design_file() {
  return {{"name", "a"},
          {"target", {{"cap", {{"diameter", 160}, {"height", 20}}}}},
          {"frame", {{"size", 200}, {"lambda", {1.5, 1.5}}}},
          {"sheet", {{"resolution", 17}}},
          {"resin", {{"min_feature", 4}, {"cell", 20}}}};
}

StencilCalibration made_up() {
  StencilCalibration c;
  c.share = {0.0, 0.04, 0.64, 1.0};
  c.density = {0.0, 0.05, 0.7, 1.0};
  c.measured = {0.05, 0.7};
  c.min_share = 0.04;
  c.max_share = 0.64;
  return c;
}

class CalibrationStore : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("membra_store_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
           "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(CalibrationStore, GivesBackWhatWasStoredForTheSameSheetOnly) {
  const auto cache = calibration_store(dir);
  const DesignSpec spec = parse_design(design_file());
  EXPECT_FALSE(cache->load(spec, 4));  // nothing yet
  cache->store(spec, 4, made_up());
  const auto back = cache->load(spec, 4);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->share, made_up().share);
  EXPECT_EQ(back->density, made_up().density);
  EXPECT_EQ(back->measured, made_up().measured);
  EXPECT_EQ(back->max_share, 0.64);
  // Another target on the same sheet shares it (the calibration does not depend on it; a cap's
  // sheet is a disk, a saddle's a square, so another cap) ...
  nlohmann::json other_target = design_file();
  other_target["name"] = "b";
  other_target["target"] = {{"cap", {{"diameter", 120}, {"height", 35}}}};
  EXPECT_TRUE(cache->load(parse_design(other_target), 4));
  // ... but not another sheet, resin, stretch, layout or number of samples.
  EXPECT_FALSE(cache->load(spec, 5));
  for (const auto& [path, value] :
       std::vector<std::pair<std::string, nlohmann::json>>{{"/sheet/resolution", 15},
                                                           {"/resin/min_feature", 5},
                                                           {"/resin/cell", 25},
                                                           {"/frame/lambda", {1.4, 1.5}}}) {
    nlohmann::json changed = design_file();
    changed[nlohmann::json::json_pointer(path)] = value;
    EXPECT_FALSE(cache->load(parse_design(changed), 4)) << path;
  }
}

TEST_F(CalibrationStore, ADamagedFileIsMeasuredAgain) {
  const auto cache = calibration_store(dir);
  const DesignSpec spec = parse_design(design_file());
  cache->store(spec, 4, made_up());
  ASSERT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  const fs::path file = fs::directory_iterator(dir)->path();
  const nlohmann::json good = nlohmann::json::parse(std::ifstream(file));
  const auto write = [&](const std::string& text) { std::ofstream(file) << text; };
  write("{\"key\": ");  // cut off
  EXPECT_FALSE(cache->load(spec, 4));
  nlohmann::json foreign = good;
  foreign["key"] = "another sheet";  // a hash collision, in effect
  write(foreign.dump());
  EXPECT_FALSE(cache->load(spec, 4));
  nlohmann::json falling = good;
  falling["density"] = {0.0, 0.7, 0.05, 1.0};
  write(falling.dump());
  EXPECT_FALSE(cache->load(spec, 4));
  cache->store(spec, 4, made_up());  // replaced
  EXPECT_TRUE(cache->load(spec, 4));
}

TEST_F(CalibrationStore, AnUnwritableDirectoryIsSkipped) {
  const auto cache = calibration_store("/proc/membra-cannot-be-here");
  const DesignSpec spec = parse_design(design_file());
  EXPECT_NO_THROW(cache->store(spec, 4, made_up()));
  EXPECT_FALSE(cache->load(spec, 4));
}

// Sets or unsets an environment variable for the life of the object, then puts it back.
class ScopedEnv {
 public:
  explicit ScopedEnv(const char* name) : name_(name) {
    const char* v = std::getenv(name);
    had_ = v != nullptr;
    if (had_) old_ = v;
  }
  ~ScopedEnv() { had_ ? ::setenv(name_, old_.c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  bool had_ = false;
  std::string old_;
};

TEST(CalibrationCacheDir, FollowsTheEnvironment) {
  const ScopedEnv own("MEMBRA_CACHE_DIR"), xdg("XDG_CACHE_HOME"), home("HOME");
  ::setenv("MEMBRA_CACHE_DIR", "/tmp/membra-x", 1);
  EXPECT_EQ(default_cache_dir(), fs::path("/tmp/membra-x"));
  ::setenv("MEMBRA_CACHE_DIR", "off", 1);
  EXPECT_TRUE(default_cache_dir().empty());
  ::unsetenv("MEMBRA_CACHE_DIR");
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(default_cache_dir(), fs::path("/tmp/xdg/membra"));
  ::unsetenv("XDG_CACHE_HOME");
  ::setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(default_cache_dir(), fs::path("/home/someone/.cache/membra"));
  ::unsetenv("HOME");
  EXPECT_TRUE(default_cache_dir().empty());
}

}  // namespace
}  // namespace membra
