// `membra run` as a process among others: Ctrl-C and SIGTERM stop it within a second, saying
// where it was, writing nothing (no staged file left behind), leaving an earlier result as it
// was, exiting 128 + the signal; a second run into the same folder is refused while the first
// writes there; a full disk ends the run with exit 4 and nothing written (docs/errors.md).
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace membra {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Stopped {
  int code = -1;       // exit code, or -1 when killed by a signal / still running
  double seconds = 0;  // from the signal to the exit
  std::string stderr_text;
};

// Starts membra with `args` (stderr to a file), sends `signal` (0: none) once `ready()` holds
// (checked every 5 ms, at most 60 s), and waits for it to end. `file_limit` > 0 caps the size of
// every file it writes (RLIMIT_FSIZE, with SIGXFSZ ignored so that writes past it fail as on a
// full disk).
Stopped run_and_signal(const std::vector<std::string>& args, const std::function<bool()>& ready,
                       int signal, const fs::path& log, rlim_t file_limit = 0) {
  std::vector<char*> argv{const_cast<char*>(MEMBRA_CLI)};  // built before fork: no allocation after
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDERR_FILENO);
    if (file_limit > 0) {
      std::signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{file_limit, file_limit};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    execv(MEMBRA_CLI, argv.data());
    _exit(127);
  }
  for (const auto start = Clock::now();
       !ready() && Clock::now() - start < std::chrono::seconds(60);)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (signal != 0) kill(pid, signal);
  const auto sent = Clock::now();
  Stopped s;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (Clock::now() - sent > std::chrono::seconds(20)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  s.seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  if (WIFEXITED(status)) s.code = WEXITSTATUS(status);
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  s.stderr_text = text.str();
  return s;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;  // files come and go while a run stages them
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(fs::relative(it->path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

class RunningCli : public ::testing::Test {
 protected:
  fs::path dir = unique_temp_dir();
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir / "out");
    std::ofstream(dir / "out" / "report.json") << "an earlier result\n";
  }
  void TearDown() override { fs::remove_all(dir); }
  int second_code = -1;
  void expect_untouched() {
    EXPECT_EQ(files_in(dir / "out"), std::vector<std::string>{"report.json"});
    std::ifstream in(dir / "out" / "report.json");
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "an earlier result");
  }
};

const std::string kExp3 = std::string(MEMBRA_SOURCE_DIR) + "/examples/exp3_parallel.json";

TEST_F(RunningCli, CtrlCStopsARunWithinASecondAndWritesNothing) {
  // exp3 at 41 x 41 with the static solver: minutes of release.
  const auto start = Clock::now();
  const auto after_1_5_s = [&] { return Clock::now() - start > std::chrono::milliseconds(1500); };
  const Stopped s = run_and_signal({"run", kExp3, "--out", (dir / "out").string(), "--quiet"},
                                   after_1_5_s, SIGINT, dir / "log");
  EXPECT_EQ(s.code, 130) << s.stderr_text;
  EXPECT_LT(s.seconds, 1.0);
  EXPECT_NE(s.stderr_text.find("stopped (SIGINT) during release"), std::string::npos)
      << s.stderr_text;
  EXPECT_NE(s.stderr_text.find("relative residual"), std::string::npos) << s.stderr_text;
  expect_untouched();
}

TEST_F(RunningCli, SigtermWhileTheOutputsAreStagedLeavesNoStagedFile) {
  // A tiny sheet (solved at once) with the largest pictures: the run spends its time staging.
  const Stopped s = run_and_signal(
      {"run", kExp3, "--out", (dir / "out").string(), "--quiet", "--set", "sheet.resolution=[9,9]",
       "--set", "output.image_size=[8192,6144]", "--set", "output.frames=6"},
      [&] {  // the first staged file (report.json's, under a temporary name) is there
        for (const auto& f : files_in(dir / "out"))
          if (f.starts_with("report.json.tmp")) return true;
        return false;
      },
      SIGTERM, dir / "log");
  EXPECT_EQ(s.code, 143) << s.stderr_text;
  EXPECT_LT(s.seconds, 3.0);  // the picture being encoded is finished first
  EXPECT_NE(s.stderr_text.find("terminated (SIGTERM) while writing the outputs"), std::string::npos)
      << s.stderr_text;
  expect_untouched();
}

TEST_F(RunningCli, ASecondRunIntoTheSameFolderIsRefusedWhileTheFirstWrites) {
  const fs::path out = dir / "out";
  const auto second_refused = [&] {
    if (!fs::exists(out / ".membra.lock")) return false;  // the first holds the folder's lock
    // At most two minutes: were the lock not taken, it would run on for minutes.
    const int code =
        std::system((std::string("timeout 120 ") + MEMBRA_CLI + " run " + kExp3 +
                     " --quiet --out " + out.string() + " 2>" + (dir / "second.log").string())
                        .c_str());
    second_code = WIFEXITED(code) ? WEXITSTATUS(code) : -1;
    return true;
  };
  const Stopped s = run_and_signal({"run", kExp3, "--out", out.string(), "--quiet"}, second_refused,
                                   SIGINT, dir / "log");
  EXPECT_EQ(second_code, 4);
  std::ifstream in(dir / "second.log");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("another membra (pid"), std::string::npos) << text.str();
  EXPECT_EQ(s.code, 130) << s.stderr_text;
  expect_untouched();  // neither wrote: the first was stopped, the second refused
}

TEST_F(RunningCli, AFullDiskEndsWithExit4NamingTheFileAndWritesNothing) {
  // Files past 64 kB cannot be written, as on a full disk: the report, the meshes and the
  // stencil of exp3's strips fit, the pictures do not.
  const Stopped s = run_and_signal(
      {"run", kExp3, "--out", (dir / "out").string(), "--quiet", "--set", "sheet.resolution=[9,9]"},
      [] { return true; }, 0, dir / "log", 64 * 1024);
  EXPECT_EQ(s.code, 4) << s.stderr_text;
  // The message names the file (the first over the cap: a picture).
  EXPECT_NE(
      s.stderr_text.find((dir / "out").string() + "/curvature.png: write failed (disk full?)"),
      std::string::npos)
      << s.stderr_text;
  expect_untouched();
}

}  // namespace
}  // namespace membra
