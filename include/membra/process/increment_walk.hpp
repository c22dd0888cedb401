#pragma once
// Where a gradual path stands and which increment comes next: the one walk along a path's
// increments that every front end takes (process/path.hpp's follow_path to the end at once, the
// viewer one increment per settled slice). Positions are counted in eighths of the scene's
// increment, so that t = k/n exactly at the scene's increments. With a second-order solver an
// increment that does not converge is undone and taken in two halves (down to an eighth), the
// length grows back after easy ones, and each starts from the secant predictor (the last
// increment's motion, scaled to this one's length). Intermediate increments are solved to the
// path tolerance (simulation.path_tolerance), the last one in full (docs/process.md).
#include <string>

#include "membra/core/vec.hpp"
#include "membra/model/model.hpp"
#include "membra/process/path.hpp"
#include "membra/process/scene.hpp"

namespace membra {

class IncrementWalk {
 public:
  IncrementWalk() = default;
  // A walk along `path` (gradual; another kind is done at once), with the scene's tolerances;
  // `adaptive`: halving, growth and the predictor (a second-order solver).
  IncrementWalk(Path path, const SimulationSpec& sim, bool adaptive);

  // Every increment accepted (a path that is not gradual: at once).
  bool done() const { return path_.kind != Path::Kind::gradual || at_ >= units(); }
  // Begins the next increment: sets the path at its end and, adaptive, moves x by the predictor,
  // no further than the self-contact of `model` allows (if given and it has any).
  // Returns the tolerance its solve should reach.
  double begin(Points& x, const Model* model = nullptr);
  // The share of the path accepted so far, in [0, 1].
  double done_fraction() const { return units() > 0 ? static_cast<double>(at_) / units() : 1.0; }
  // The position at the end of the increment begun, in (0, 1].
  double t() const { return static_cast<double>(next_) / units(); }
  // The tolerance the increment begun is to be solved to (as begin returned).
  double tolerance() const { return next_ == units() ? tolerance_ : path_tolerance_; }
  // "release 3/10", or "release 35%" between the scene's increments.
  std::string stage(const std::string& name) const;
  // The increment's solve did not converge: true when it was undone (x back at its start) to be
  // taken in two halves; false when it cannot be halved (not adaptive, or an eighth already).
  bool halve(Points& x);
  // The increment begun is done at x; `iterations` its solve's (easy ones let the length grow).
  void accept(const Points& x, long iterations);

 private:
  static constexpr int kEighths = 8;
  int units() const { return kEighths * path_.increments; }

  Path path_;
  double tolerance_ = 0.0, path_tolerance_ = 0.0;
  bool adaptive_ = false;
  int at_ = 0, next_ = 0, step_ = kEighths, last_step_ = 0;
  Points start_;   // x when the increment began
  Points motion_;  // the equilibrium's change over the last accepted increment
};

}  // namespace membra
