#include "membra/process/increment_walk.hpp"

#include <algorithm>
#include <cmath>

namespace membra {

IncrementWalk::IncrementWalk(Path path, const SimulationSpec& sim, bool adaptive)
    : path_(std::move(path)),
      tolerance_(sim.tolerance),
      path_tolerance_(sim.path_tolerance),
      adaptive_(adaptive) {}

double IncrementWalk::begin(Points& x, const Model* model) {
  next_ = std::min(units(), at_ + step_);
  start_ = x;
  path_.set(t());
  if (adaptive_ && motion_.cols() == x.cols()) {
    // A predictor that would carry the sheet through itself is shortened (self_contact.hpp).
    const Points step = (static_cast<double>(next_ - at_) / last_step_) * motion_;
    if (model) model->self_contact.refresh(x);
    x += (model ? model->self_contact.step_limit(x, step, Points()) : 1.0) * step;
  }
  // Intermediate increments only carry the sheet along the path: a looser tolerance there saves
  // their slow tails; the last one is solved in full.
  return tolerance();
}

std::string IncrementWalk::stage(const std::string& name) const {
  const int n = path_.increments;
  const double k = t() * n;
  if (std::abs(k - std::round(k)) < 1e-9)
    return name + " " + std::to_string(static_cast<int>(std::round(k))) + "/" + std::to_string(n);
  return name + " " + std::to_string(static_cast<int>(std::round(100.0 * t()))) + "%";
}

bool IncrementWalk::halve(Points& x) {
  if (!adaptive_ || step_ <= 1) return false;
  x = start_;
  step_ /= 2;
  return true;
}

void IncrementWalk::accept(const Points& x, long iterations) {
  motion_ = x - start_;
  last_step_ = next_ - at_;
  at_ = next_;
  if (adaptive_ && step_ < kEighths && iterations < 30) step_ = std::min(kEighths, 2 * step_);
}

}  // namespace membra
