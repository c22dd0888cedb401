// Outputs appear all together or not at all.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "test_util.hpp"

#include "membra/output/output_set.hpp"

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

TEST_F(OutputSetTest, AFolderHasOneWriterAtATime) {
  {
    OutputSet first(dir);
    first.add("a.txt", [](std::ostream& os) { os << "first"; });
    try {
      OutputSet second(dir);
      FAIL() << "a second writer was let in";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find("another membra (pid " + std::to_string(getpid())),
                std::string::npos)
          << e.what();
    }
    first.commit();
  }
  EXPECT_EQ(files_in(dir), 1) << "the lock file goes with its writer";
  OutputSet third(dir);  // the folder is free again
}

TEST_F(OutputSetTest, DroppedFoldersMadeForStagedFilesGoToo) {
  fs::create_directories(dir);
  {
    OutputSet out(dir);
    out.add("frames/f1.png", [](std::ostream& os) { os << "x"; });
    out.add("branches/1/final.obj", [](std::ostream& os) { os << "y"; });
  }
  EXPECT_EQ(files_in(dir), 0);
}

}  // namespace
}  // namespace membra
