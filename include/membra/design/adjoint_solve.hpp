#pragma once
// The adjoint system of an equilibrium: H w = r, with H the Hessian of the potential energy at
// a stable equilibrium x. A sheet held by nothing has six rigid motions in H's null space; the
// right-hand side of a rigid-invariant objective is orthogonal to them, so the system is solved
// in the rigid gauge of the Newton solver (solve/rigid_gauge.hpp), which fixes exactly those
// six motions. Pinned particles are held. Then for a parameter p of the model,
// dJ/dp = -w . d(grad E)/dp (docs/inverse_design.md).
#include <optional>

#include "membra/model/model.hpp"

namespace membra {

// w, or nothing when H is not positive definite on the free coordinates (not a stable minimum).
std::optional<Points> solve_adjoint(const Model& model, const Points& x, const Points& rhs);

}  // namespace membra
