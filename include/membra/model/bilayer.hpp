#pragma once
// Resin on one face: the bilayer's spontaneous curvature and the hinges that carry it
// (hinges.hpp; docs/process.md "Bilayer").
#include "membra/model/material.hpp"
#include "membra/model/membrane.hpp"
#include "membra/model/pattern.hpp"

namespace membra {

// Curvature per unit misfit strain (1/m) of a strip of `base` with a bonded `layer` whose
// natural length differs by the strain eps: kappa = eps * T / h, h = t_base + t_layer, with
// Timoshenko's bimetal factor T = 6 (1 + m)^2 / (3 (1 + m)^2 + (1 + m n)(m^2 + 1 / (m n))),
// m = t_layer / t_base, n = E_layer / E_base. The layer is on the convex side when it is the
// longer one. For a plate with equal Poisson ratios the same factor maps the misfit strain
// tensor to the curvature tensor.
double bilayer_curvature_per_strain(const Material& base, const Material& layer);

// Adds hinges inside `pattern` whose moments make the released composite curl with the resin on
// the `side` face (+1 top, -1 bottom). The misfit is the latex's current stretch: eps = I - V^-1,
// V the in-plane stretch of the hinge's two triangles from the paper to the frame. A hinge the
// pattern covers by a share f takes f of the spontaneous curvature at the stiffness of coat and
// bare latex in series (so a coat's edge does not crease); a hinge an earlier coat covers in part
// takes the rest from this one, up to the whole. The moments act in proportion to the release
// (none before it). Returns the number of hinges with resin.
// `all_coats`: the union of the coats since the sheet last moved, this one included (null: this
// one alone), which decides how much of a hinge an earlier coat leaves to this one.
int add_bilayer_hinges(Membrane& m, const Pattern& pattern, const Material& resin, int side,
                       const Pattern* all_coats = nullptr);

// Sets the hinges' moments for the membrane's release level (full moment times the share of
// the misfit released so far).
void update_hinge_moments(Membrane& m);

}  // namespace membra
