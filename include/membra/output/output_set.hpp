#pragma once
// Writes a run's output files all-or-nothing: each file goes to a temporary name in the output
// directory, and only commit() renames them into place. If anything fails before commit(), the
// destructor removes the temporaries (and the folders made for them), so a failed or interrupted
// run leaves no partial or stale-looking files.
#include <filesystem>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace membra {

// Failure to create, write or move an output file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputSet {
 public:
  // Creates `dir` if needed, checks it is writable and takes its lock (DIR/.membra.lock, an
  // flock held while the set lives). Throws OutputError naming the directory when it cannot be
  // created or written, or when another OutputSet (another membra) holds it.
  explicit OutputSet(std::filesystem::path dir);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Stages file `name` by calling write(stream). Throws OutputError naming the file if
  // writing fails (disk full, I/O error), Interrupted if a stop was requested
  // (core/stop_request.hpp).
  void add(const std::string& name, const std::function<void(std::ostream&)>& write);
  // Renames every staged file to its final name; throws Interrupted instead, moving nothing,
  // if a stop was requested.
  void commit();
  const std::filesystem::path& dir() const { return dir_; }
  // The temporary file holding staged `name` (to read back what was written), or an empty path.
  std::filesystem::path staged(const std::string& name) const;
  // The names of the staged files, relative to dir(), in the order they were added.
  std::vector<std::string> names() const;

 private:
  std::filesystem::path dir_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // tmp, final
  std::vector<std::filesystem::path> created_dirs_;                              // outermost first
  int lock_fd_ = -1;  // DIR/.membra.lock, held while the set lives
  bool committed_ = false;
};

}  // namespace membra
