#include "progress_bar.hpp"

#include <cstdio>
#include <string>

#include <unistd.h>

namespace membra::cli {
namespace {

// "40 s", "3 min 20 s", "1 h 5 min".
std::string readable_seconds(double s) {
  char text[32];
  if (s < 60.0)
    std::snprintf(text, sizeof text, "%.0f s", s);
  else if (s < 3600.0)
    std::snprintf(text, sizeof text, "%d min %02d s", int(s / 60.0), int(s) % 60);
  else
    std::snprintf(text, sizeof text, "%d h %02d min", int(s / 3600.0), int(s / 60.0) % 60);
  return text;
}

}  // namespace

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
  // The bar shows the whole run (its steps weighted by their increments) where the run knows it,
  // else the solve's iterations out of its cap.
  const bool whole = p.run_done >= 0.0;
  const double frac = whole                  ? p.run_done
                      : p.max_iterations > 0 ? double(p.iteration) / double(p.max_iterations)
                                             : 1.0;
  constexpr int width = 30;
  const int filled = static_cast<int>(frac * width);
  char bar[width + 1];
  for (int i = 0; i < width; ++i) bar[i] = i < filled ? '#' : '.';
  bar[width] = '\0';
  // Time left from the share done so far, once there is a share to go by.
  char left[48] = "";
  if (whole && frac >= 0.05 && frac < 1.0)
    std::snprintf(left, sizeof left, ", about %s left",
                  readable_seconds(now * (1.0 - frac) / frac).c_str());
  // The stage ("release 3/10", "32x32 release 3/10" on a multilevel run's coarser grid), the
  // share done, the solve's iteration and residual, and the run's time so far; a terminal's line
  // is cleared to its end.
  std::fprintf(stderr, "%s%s [%s] %3.0f%%  iteration %ld  residual %.2e  %.1f s%s%s",
               tty_ ? "\r" : "", p.stage.c_str(), bar, 100.0 * frac, p.iteration,
               p.residual_relative, now, left, tty_ ? "\x1b[K" : "\n");
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::finish() {
  if (drawn_ && tty_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace membra::cli
