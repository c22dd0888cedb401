#pragma once
// Gaussian curvature density on an irregular triangle mesh from a fitted surface: at each
// interior vertex, the height z = a x^2 + b x y + c y^2 + d x + e y of its two rings of
// neighbours, in the tangent frame of its area-weighted normal, fitted by least squares; K is
// the fitted graph's, (4 a c - b^2) / (1 + d^2 + e^2)^2. Angle defects divided by a vertex's area
// are exact in sum (Gauss-Bonnet) but scatter from vertex to vertex on an irregular mesh, by as
// much as the curvature itself; the fit reads the smooth field the pictures should show
// (docs/measures.md, "On meshes").
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/measure/curvature.hpp"

namespace membra {

// One value per vertex, 1/m^2, at the vertices `interior` marks (0 elsewhere, and where the
// neighbourhood is too small or flat in the tangent frame to fit).
std::vector<double> fitted_gaussian_curvature(const Points& x, const std::vector<Triangle>& tris,
                                              const std::vector<bool>& interior);

// Makes the fitted field k's density (set_smoothed_density): the continuum's counterpart of
// smooth_density_on_grid. `total` stays the exact sum of the angle defects.
void smooth_density_on_mesh(const Points& x, const std::vector<Triangle>& tris,
                            GaussianCurvature& k);

}  // namespace membra
