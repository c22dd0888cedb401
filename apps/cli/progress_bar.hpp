#pragma once
// A progress bar on stderr that appears only once a run has taken more than a second.
#include "membra/core/stopwatch.hpp"
#include "membra/solve/solve_report.hpp"

namespace membra::cli {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled);
  ~ProgressBar();
  void update(const Progress& p);
  // Ends the bar's line (if one was drawn).
  void finish();

 private:
  bool enabled_;
  bool tty_;
  bool drawn_ = false;
  double last_print_ = -1e9;
  Stopwatch clock_;  // the run's time: a solve's own clock starts again at each increment
};

}  // namespace membra::cli
