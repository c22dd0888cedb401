#pragma once
// Summaries of a form: how far it rises out of its best-fit plane, its bounding box, and how
// much of that rise is the global shape and how much local folding.
#include "membra/core/vec.hpp"
#include "membra/measure/quadric_fit.hpp"

namespace membra {

struct ShapeSummary {
  double height = 0.0;   // extent along the normal of the least-squares plane, m
  double z_range = 0.0;  // max z - min z, m
  Vec3 bbox_min = Vec3::Zero(), bbox_max = Vec3::Zero();  // m
  Vec3 normal = Vec3::UnitZ();  // normal of the least-squares plane (smallest principal axis)
  // The rise split by scale, over each particle's neighbourhood on the paper (the particles
  // within 1/16 of the sheet's size, a window 1/8 of the sheet across): the neighbourhoods' mean
  // positions are the global form; a particle's distance from its neighbourhood's least-squares
  // plane is its fold. Zero when no paper positions are given.
  double global_height = 0.0;  // `height` of the global form, m
  double fold_rms = 0.0;       // rms of the particles' folds, m
  double fold_max = 0.0;       // largest fold, m
  QuadricFit quadric;          // the whole form's best-fit quadric (quadric_fit.hpp)
};

// Shape summary of a point set (3 x N, N >= 1). The best-fit plane makes `height` independent of
// how the released sheet happens to lie in space. `paper`, when given (3 x N, the particles'
// positions in the flat sheet), defines the neighbourhoods of the global/fold split and the
// parametrisation of the quadric fit.
ShapeSummary summarize_shape(const Points& x, const Points& paper = Points());

// The global form: each particle moved to the linear least-squares fit of the positions over its
// paper neighbourhood (the window of summarize_shape's split, 1/8 of the sheet across), evaluated
// at the particle: the neighbourhood's mean inside the sheet, unbiased at its edges. Folds and
// wrinkles finer than the window average out and the form a designer sees remains. Empty when
// `paper` does not match x.
Points global_form(const Points& x, const Points& paper);

// Extent of x along the normal of its least-squares plane (that normal is returned in `normal`).
double height_over_best_plane(const Points& x, Vec3* normal = nullptr);

}  // namespace membra
