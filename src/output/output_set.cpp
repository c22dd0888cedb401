#include "membra/output/output_set.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

#include "membra/core/stop_request.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace membra {
namespace fs = std::filesystem;

namespace {
std::string tmp_suffix() {
  return ".tmp-" + std::to_string(::getpid());
}

const char* const kLockName = ".membra.lock";

// The pid another writer left in the lock file, for the message.
std::string lock_holder(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string("?");
}

// Takes the directory's lock: an exclusive flock on DIR/.membra.lock, without waiting. Returns
// the file descriptor, or throws OutputError naming the other writer. Retries when the file was
// removed between its opening and the lock (its last holder leaving).
int take_lock(const fs::path& dir) {
  const fs::path file = dir / kLockName;
  for (int attempt = 0; attempt < 5; ++attempt) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw OutputError("output directory " + dir.string() + ": cannot create its lock");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string pid = lock_holder(fd);
      ::close(fd);
      throw OutputError("output directory " + dir.string() + ": another membra (pid " + pid +
                        ") is writing its results there; wait for it to finish or choose "
                        "another output directory");
    }
    struct stat held {
    }, named{};
    if (::fstat(fd, &held) == 0 && ::stat(file.c_str(), &named) == 0 &&
        held.st_ino == named.st_ino && held.st_dev == named.st_dev) {
      const std::string pid = std::to_string(::getpid());
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
        // The pid is only for the other writer's message.
      }
      return fd;
    }
    ::close(fd);  // locked a file already unlinked: take the new one
  }
  throw OutputError("output directory " + dir.string() + ": cannot take its lock");
}
}  // namespace

OutputSet::OutputSet(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_))
    throw OutputError("output directory " + dir_.string() + ": cannot create it (" +
                      (ec ? ec.message() : "not a directory") + ")");
  // Probe with a real file: permission bits alone do not tell (root, read-only mounts).
  const fs::path probe = dir_ / (".membra-write-test" + tmp_suffix());
  {
    std::ofstream out(probe);
    if (!out) throw OutputError("output directory " + dir_.string() + ": not writable");
  }
  fs::remove(probe, ec);
  // One writer at a time: a second run into the same folder is refused, so that two sets of
  // results never interleave (docs/errors.md).
  lock_fd_ = take_lock(dir_);
}

OutputSet::~OutputSet() {
  std::error_code ec;
  if (!committed_) {
    for (const auto& [tmp, final_path] : staged_) fs::remove(tmp, ec);
    // The folders made for staged files (frames/), deepest first, if nothing else is in them.
    for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it)
      if (fs::is_empty(*it, ec)) fs::remove(*it, ec);
  }
  // The lock last, so that the next writer finds the folder cleaned up.
  if (lock_fd_ >= 0) {
    fs::remove(dir_ / kLockName, ec);  // unlinked while still held: see take_lock
    ::close(lock_fd_);
  }
}

fs::path OutputSet::staged(const std::string& name) const {
  for (const auto& [tmp, final_path] : staged_)
    if (final_path == dir_ / name) return tmp;
  return {};
}

std::vector<std::string> OutputSet::names() const {
  std::vector<std::string> out;
  for (const auto& [tmp, final_path] : staged_)
    out.push_back(final_path.lexically_relative(dir_).generic_string());
  return out;
}

void OutputSet::add(const std::string& name, const std::function<void(std::ostream&)>& write) {
  // A stop asked for (Ctrl-C) while the outputs are being written: drop them all, here.
  if (const int sig = stop_requested()) throw Interrupted(sig, "while writing the outputs");
  const fs::path final_path = dir_ / name;
  const fs::path tmp = dir_ / (name + tmp_suffix());
  std::error_code ec;
  // Names may have folders (frames/f.png, branches/1/final.obj): made here, and removed again
  // when the set is dropped before commit.
  for (fs::path d = final_path.parent_path(); d != dir_ && !fs::exists(d, ec); d = d.parent_path())
    created_dirs_.insert(created_dirs_.begin(), d);
  fs::create_directories(final_path.parent_path(), ec);
  staged_.emplace_back(tmp, final_path);
  std::ofstream out(tmp, std::ios::binary);
  if (!out) throw OutputError(tmp.string() + ": cannot open for writing");
  write(out);
  out.flush();
  if (!out) throw OutputError(final_path.string() + ": write failed (disk full?)");
}

void OutputSet::commit() {
  // A stop asked for after the last file was staged: still nothing moves into place.
  if (const int sig = stop_requested()) throw Interrupted(sig, "while writing the outputs");
  for (const auto& [tmp, final_path] : staged_) {
    std::error_code ec;
    fs::rename(tmp, final_path, ec);
    if (ec) throw OutputError(final_path.string() + ": cannot move into place: " + ec.message());
  }
  committed_ = true;
}

}  // namespace membra
