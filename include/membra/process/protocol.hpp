#pragma once
// The protocol: the ordered steps of the material process (docs/process.md), each kind its own
// struct, in SI, with no file format in it. A step that changes the sheet gradually carries the
// settings of its path (path.hpp); patterns and fields carry their descriptions beside the shapes
// built from them, so that a scene can be written back (io/scene_writer.hpp).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "membra/model/elements/added_springs.hpp"
#include "membra/model/field_spec.hpp"
#include "membra/model/grow.hpp"
#include "membra/model/material.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"
#include "membra/model/pattern_spec.hpp"
#include "membra/model/pins.hpp"

namespace membra {

// How a gradual step is followed: increments of the quasi-static path (equilibrium solvers) and
// the symmetry-breaking bump applied before it.
struct PathSettings {
  int increments = 10;
  double perturbation = 0.2e-3;  // m
  std::uint64_t seed = 1;
  // The bump towards the resin side (perturb), or a random mix of low modes (perturb_randomly),
  // which simulation.explore uses for its further releases.
  bool random_imperfection = false;
};

// The frame pins the sheet's held edges and stretches it by lambda.
struct StretchStep {
  Vec2 lambda{1.0, 1.0};
  FrameEdges hold;
};

// Resin soaks the springs under the pattern (frame coordinates) and cures at their length.
struct ImpregnateStep {
  PatternSpec pattern_spec;  // the pattern as described ...
  PatternPtr pattern;        // ... and its shape
  Material resin = epoxy();
  int resin_side = +1;   // +1 top, -1 bottom
  bool bilayer = false;  // resin on that face only: the composite curls on release
};

// The frame lets go: the latex returns to its natural length along the path.
struct ReleaseStep {
  PathSettings path;
};

// Gravity changes and/or more particles are pinned.
struct LoadStep {
  std::optional<double> gravity;  // m/s^2 along -z
  std::vector<PinSpec> pins;
};

// Intrinsic deformation: natural lengths scaled by a field.
struct GrowStep {
  GrowSpec grow;  // the factor as a function, the region as a shape
  FieldSpec factor;
  std::optional<PatternSpec> region;
  PathSettings path;
};

// Extrinsic deformation: springs added in a region (stiffness 0: the sheet's own).
struct AddSpringsStep {
  AddSpringsSpec add;  // the region as a shape
  PatternSpec region;
  PathSettings path;
  bool along_given = false;  // "along" was in the scene (a mesh has no spring families)
};

// Topological change: a polyline cut (frame coordinates, m) and/or a hole.
struct CutStep {
  std::vector<Vec2> line;
  std::optional<PatternSpec> hole_spec;
  PatternPtr hole;
  // A cut drawn after the sheet moved off its frame, pulled back through where the sheet lay
  // (process/cut_after_motion.hpp): its line and hole then name natural-sheet points times the
  // frame's stretch, as a cut on the frame does, and the continuum's mesh follows them.
  bool on_paper = false;
};

// Form from a Gaussian-curvature map: the target K (1/m^2) at a paper position (m).
struct CurvatureMapStep {
  std::function<double(const Vec2&)> curvature;
  FieldSpec field;  // as described, in 1/mm^2
  PathSettings path;
};

struct ProtocolStep {
  // In the order of the variant's alternatives.
  enum class Kind { stretch, impregnate, release, load, grow, add_springs, cut, curvature_map };
  using Variant = std::variant<StretchStep, ImpregnateStep, ReleaseStep, LoadStep, GrowStep,
                               AddSpringsStep, CutStep, CurvatureMapStep>;

  std::string pointer;  // "/protocol/2", for messages
  Variant step;

  Kind kind() const { return static_cast<Kind>(step.index()); }
  // The step as its kind, or nullptr when it is another kind.
  template <class T>
  const T* as() const {
    return std::get_if<T>(&step);
  }
  template <class T>
  T* as() {
    return std::get_if<T>(&step);
  }
};

// The kind as scenes write it ("stretch", "add_springs", ...).
const char* step_name(ProtocolStep::Kind kind);

}  // namespace membra
