#pragma once
// A request from outside to stop a long run: the CLI's SIGINT/SIGTERM handler sets it, and the
// runs check it at each progress report (and before their outputs are committed), throwing
// Interrupted, which says where the run was. A flag, not an exception from the handler: a
// signal handler may only store to a lock-free atomic.
#include <atomic>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "membra/core/progress.hpp"

namespace membra {

inline std::atomic<int> g_stop_signal{0};  // 0, or the signal that asked for the stop

inline void request_stop(int signal) {
  g_stop_signal.store(signal);
}
inline int stop_requested() {
  return g_stop_signal.load();
}

// Thrown when a stop was requested: nothing after it is written.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& where)
      : std::runtime_error("interrupted " + where), signal_(signal), where_(where) {}
  int signal() const { return signal_; }
  const std::string& where() const { return where_; }  // "during release 3/10, iteration 5, ..."

 private:
  int signal_;
  std::string where_;
};

// Throws Interrupted, naming the stage, iteration and residual of `p`, if a stop was requested.
inline void throw_if_stop_requested(const Progress& p) {
  if (const int s = stop_requested()) {
    char residual[32];
    std::snprintf(residual, sizeof residual, "%.3g", p.residual_relative);
    throw Interrupted(s, "during " + (p.stage.empty() ? std::string("the solve") : p.stage) +
                             ", iteration " + std::to_string(p.iteration) + ", relative residual " +
                             residual);
  }
}

}  // namespace membra
