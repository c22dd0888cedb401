#pragma once
// A table of per-element rows built on first use and dropped when what it is built from
// changes: the shell triangles' plans, which depend on the rest state only and so are the same
// for every force pass between two steps (docs/performance.md, "The shell's plans"). The first
// use is thread-safe (the kernels run over ranges on several threads). Built rows never change,
// so copies share them (a viewer's undo snapshot costs a pointer) and a move takes them along.
#include <atomic>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace membra {

template <class Row>
class LazyTable {
 public:
  LazyTable() = default;
  LazyTable(const LazyTable& o) {
    const std::lock_guard lock(o.mutex_);
    rows_ = o.rows_;
    built_.store(o.built_.load(std::memory_order_relaxed), std::memory_order_relaxed);
  }
  LazyTable& operator=(const LazyTable& o) {
    if (this == &o) return *this;
    const std::scoped_lock lock(mutex_, o.mutex_);
    rows_ = o.rows_;
    built_.store(o.built_.load(std::memory_order_relaxed), std::memory_order_relaxed);
    return *this;
  }
  // Moves are not concurrent with get() (whoever moves a set owns it): no lock.
  LazyTable(LazyTable&& o) noexcept : rows_(std::move(o.rows_)) {
    built_.store(o.built_.exchange(false, std::memory_order_relaxed), std::memory_order_relaxed);
  }
  LazyTable& operator=(LazyTable&& o) noexcept {
    if (this == &o) return *this;
    rows_ = std::move(o.rows_);
    built_.store(o.built_.exchange(false, std::memory_order_relaxed), std::memory_order_relaxed);
    return *this;
  }
  ~LazyTable() = default;

  // Drops the rows: the next get() builds them again.
  void clear() {
    const std::lock_guard lock(mutex_);
    rows_.reset();
    built_.store(false, std::memory_order_release);
  }
  // The rows, built by build() (returning std::vector<Row>) if they are not there.
  template <class Build>
  const std::vector<Row>& get(Build&& build) const {
    if (!built_.load(std::memory_order_acquire)) {
      const std::lock_guard lock(mutex_);
      if (!built_.load(std::memory_order_relaxed)) {
        rows_ = std::make_shared<const std::vector<Row>>(build());
        built_.store(true, std::memory_order_release);
      }
    }
    return *rows_;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const std::vector<Row>> rows_;
  mutable std::atomic<bool> built_{false};
};

}  // namespace membra
