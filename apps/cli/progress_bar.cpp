#include "progress_bar.hpp"

#include <cstdio>

#include <unistd.h>

namespace membra::cli {

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), tty_(::isatty(STDERR_FILENO) != 0) {}

ProgressBar::~ProgressBar() {
  finish();
}

void ProgressBar::update(const Progress& p) {
  const double now = clock_.seconds();
  if (!enabled_ || now < 1.0) return;
  // A terminal gets a bar redrawn in place; a log file gets a line every 5 s.
  const double interval = tty_ ? 0.1 : 5.0;
  if (now - last_print_ < interval) return;
  last_print_ = now;
  const double frac = p.max_iterations > 0 ? double(p.iteration) / double(p.max_iterations) : 1.0;
  constexpr int width = 30;
  const int filled = static_cast<int>(frac * width);
  char bar[width + 1];
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
  bar[width] = '\0';
  // The stage ("release 3/10", "32x32 release 3/10" on a multilevel run's coarser grid), the
  // solve's progress, and the run's time so far; a terminal's line is cleared to its end.
  std::fprintf(stderr, "%s%s [%s] %3.0f%%  step %ld/%ld  residual %.2e  %.1f s%s", tty_ ? "\r" : "",
               p.stage.c_str(), bar, 100.0 * frac, p.iteration, p.max_iterations,
               p.residual_relative, now, tty_ ? "\x1b[K" : "\n");
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_ && tty_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace membra::cli
