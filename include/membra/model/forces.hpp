#pragma once
// Net forces and energies of a model at given positions and velocities.
#include "membra/model/model.hpp"

namespace membra {

// Computes the net force (N) on every particle into f (resized to 3 x N): springs (elastic and
// damping along the spring), every other element set, gravity m g, and global velocity damping -D m
// v. Pinned particles get a force too; integrators ignore it. Pass an empty v for a static
// evaluation (no damping).
void compute_forces(const Model& model, const Points& x, const Points& v, Points& f);

// Static force (every element set without damping, and gravity): what must vanish at equilibrium.
void compute_static_forces(const Model& model, const Points& x, Points& f);

// The energy of every element set that stores `kind` (J).
double energy_of_kind(const Model& model, const Points& x, EnergyKind kind);
// Stretching energy (J): energy_of_kind(stretching).
double elastic_energy(const Model& model, const Points& x);
// Bending energy (J): energy_of_kind(bending), bilayer moments included.
double bending_energy(const Model& model, const Points& x);
// Gravitational potential energy sum m (-g . x) (J), zero at x = 0.
double gravity_energy(const Model& model, const Points& x);
// Potential energy: every element set's, then gravitational (J). Its negative gradient is the
// static force.
double potential_energy(const Model& model, const Points& x);
// Kinetic energy of the free particles (J).
double kinetic_energy(const Model& model, const Points& v);

// Equilibrium residual: the largest |static force| over free particles (N).
double max_residual_force(const Model& model, const Points& x);
// The largest |f| over free particles of an already computed force array (N).
double max_free_force(const Model& model, const Points& f);

}  // namespace membra
