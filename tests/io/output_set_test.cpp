// Outputs appear all together or not at all.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "test_util.hpp"

#include "membra/io/output_set.hpp"

namespace membra {
namespace {
namespace fs = std::filesystem;

class OutputSetTest : public ::testing::Test {
 protected:
  fs::path dir = unique_temp_dir();
  void SetUp() override { fs::remove_all(dir); }
  void TearDown() override { fs::remove_all(dir); }
  static int files_in(const fs::path& d) {
    int n = 0;
    for (auto it = fs::directory_iterator(d); it != fs::directory_iterator(); ++it) ++n;
    return n;
  }
};

TEST_F(OutputSetTest, CommitMovesEveryFileIntoPlace) {
  {
    OutputSet out(dir / "nested");
    out.add("a.txt", [](std::ostream& os) { os << "alpha"; });
    out.add("b.txt", [](std::ostream& os) { os << "beta"; });
    EXPECT_FALSE(fs::exists(dir / "nested/a.txt"));
    out.commit();
  }
  std::ifstream in(dir / "nested/a.txt");
  std::string s;
  in >> s;
  EXPECT_EQ(s, "alpha");
  EXPECT_EQ(files_in(dir / "nested"), 2);
}

TEST_F(OutputSetTest, NothingIsLeftWithoutCommit) {
  try {
    OutputSet out(dir);
    out.add("a.txt", [](std::ostream& os) { os << "alpha"; });
    out.add("b.txt", [](std::ostream&) { throw std::runtime_error("writer failed"); });
    out.commit();
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(files_in(dir), 0);
}

TEST_F(OutputSetTest, UncreatableDirectoryIsAnOutputError) {
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  EXPECT_THROW(OutputSet(dir / "file" / "sub"), OutputError);
}

}  // namespace
}  // namespace membra
