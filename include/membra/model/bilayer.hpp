#pragma once
// Resin on one face: the bilayer's spontaneous curvature and the hinges that carry it
// (elements/hinges.hpp; docs/process.md "Bilayer").
#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/model/material.hpp"

namespace membra {

// Curvature per unit misfit strain (1/m) of a strip of `base` with a bonded `layer` whose
// natural length differs by the strain eps: kappa = eps * T / h, h = t_base + t_layer, with
// Timoshenko's bimetal factor T = 6 (1 + m)^2 / (3 (1 + m)^2 + (1 + m n)(m^2 + 1 / (m n))),
// m = t_layer / t_base, n = E_layer / E_base. The layer is on the convex side when it is the
// longer one. For a plate with equal Poisson ratios the same factor maps the misfit strain
// tensor to the curvature tensor.
double bilayer_curvature_per_strain(const Material& base, const Material& layer);

// The in-plane deformation gradient of triangle (a, b, c) from the natural sheet (`reference`)
// to the positions x, seen from above.
Eigen::Matrix2d in_plane_gradient(const Points& reference, const Points& x, int a, int b, int c);

// eps = I - V^-1 with V = sqrt(F F^T), F the in-plane deformation gradient from the natural
// sheet to the state the coat sets in: the strain by which the latex, bonded to resin at rest in
// that state, would shorten along each direction if it were free.
Eigen::Matrix2d misfit_strain(const Eigen::Matrix2d& f);

}  // namespace membra
