#pragma once
// The Gaussian curvature of the global form (shape.hpp): the angle defects of global_form, with
// the density averaged over windows on the paper twice the form's radius (through
// paper_windows.hpp on small sheets; summed by grid rows on big ones, where those thin).
// The global form has the wrinkles finer than its window averaged out of its positions; waves
// about as long as that window (a ring of resin squares wrinkling the rim of a bowl) survive in
// part, with curvature of both signs in turn, and the density's average over the wider window
// cancels them, so that `positive` and `negative` are the form's and a bowl with a wrinkled rim
// reads as a bowl. `total` is the global form's own, untouched by the averaging.
// docs/measures.md.
#include <vector>

#include "membra/measure/curvature.hpp"

namespace membra {

// x: the form (3 x N); paper: the particles' positions in the flat sheet; tris: the sheet's
// triangles. Empty (no vertices) when `paper` does not match x.
GaussianCurvature global_curvature(const Points& x, const Points& paper,
                                   const std::vector<Triangle>& tris);

// The density of `k` averaged over each interior vertex's window: the window's interior angle
// defects over their areas; min/max density, positive and negative follow it. `paper` holds one
// position per vertex of `k`, and radius > 0 (else std::invalid_argument).
void average_density_over_windows(const Points& paper, double radius, GaussianCurvature& k);

}  // namespace membra
