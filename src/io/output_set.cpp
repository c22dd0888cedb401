#include "membra/io/output_set.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

#include "membra/core/stop_request.hpp"

#include <unistd.h>

namespace membra {
namespace fs = std::filesystem;

namespace {
std::string tmp_suffix() {
  return ".tmp-" + std::to_string(::getpid());
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
}

OutputSet::~OutputSet() {
  if (committed_) return;
  std::error_code ec;
  for (const auto& [tmp, final_path] : staged_) fs::remove(tmp, ec);
  // The folders made for staged files (frames/), deepest first, if nothing else is in them.
  for (auto it = created_dirs_.rbegin(); it != created_dirs_.rend(); ++it)
    if (fs::is_empty(*it, ec)) fs::remove(*it, ec);
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
  for (const auto& [tmp, final_path] : staged_) {
    std::error_code ec;
    fs::rename(tmp, final_path, ec);
    if (ec) throw OutputError(final_path.string() + ": cannot move into place: " + ec.message());
  }
  committed_ = true;
}

}  // namespace membra
