#pragma once
// A table of per-element rows built on first use and dropped when what it is built from
// changes: the shell triangles' plans, which depend on the rest state only and so are the same
// for every force pass between two steps (docs/performance.md, "The shell's plans"). The first
// use is thread-safe (the kernels run over ranges on several threads); copies carry the table.
#include <atomic>
#include <mutex>
#include <vector>

namespace membra {

template <class Row>
class LazyTable {
 public:
  LazyTable() = default;
  LazyTable(const LazyTable& o) { copy_from(o); }
  LazyTable& operator=(const LazyTable& o) {
    if (this != &o) copy_from(o);
    return *this;
  }
  ~LazyTable() = default;

  // Drops the rows: the next get() builds them again.
  void clear() {
    const std::lock_guard lock(mutex_);
    rows_.clear();
    built_.store(false, std::memory_order_release);
  }
  // The rows, built by build() (returning std::vector<Row>) if they are not there.
  template <class Build>
  const std::vector<Row>& get(Build&& build) const {
    if (!built_.load(std::memory_order_acquire)) {
      const std::lock_guard lock(mutex_);
      if (!built_.load(std::memory_order_relaxed)) {
        rows_ = build();
        built_.store(true, std::memory_order_release);
      }
    }
    return rows_;
  }

 private:
  void copy_from(const LazyTable& o) {
    const std::scoped_lock lock(mutex_, o.mutex_);
    rows_ = o.rows_;
    built_.store(o.built_.load(std::memory_order_relaxed), std::memory_order_relaxed);
  }

  mutable std::mutex mutex_;
  mutable std::vector<Row> rows_;
  mutable std::atomic<bool> built_{false};
};

}  // namespace membra
