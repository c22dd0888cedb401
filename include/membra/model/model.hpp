#pragma once
// The constant model (masses, springs, loads) kept apart from the changing state (positions,
// velocities), like MuJoCo's mjModel / mjData. Protocol steps change the model between solves;
// solvers only change the state.
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/elements/added_springs.hpp"
#include "membra/model/elements/bending.hpp"
#include "membra/model/elements/hinges.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/elements/self_contact.hpp"
#include "membra/model/elements/shell_triangles.hpp"
#include "membra/model/elements/springs.hpp"
#include "membra/model/elements/table_contact.hpp"

namespace membra {

struct Model {
  std::vector<double> mass;      // kg, lumped
  std::vector<double> inv_mass;  // 1/kg; 0 means pinned
  Springs springs;
  AddedSprings added_springs;  // add_springs' springs; empty unless the protocol adds some
  Bending bending;             // plate bending; empty when the sheet has none
  Hinges hinges;               // bilayer moments; empty unless resin was applied as a bilayer
  MembraneTriangles membrane_triangles;  // the continuum sheet; empty on a lattice
  ShellTriangles shell_triangles;        // its bending; empty on a lattice
  TableContact table;  // the plane the piece rests on; empty unless simulation.support is "table"
  SelfContact self_contact;       // the continuum sheet against itself; empty unless asked for
  Points reference;               // paper position of each particle in the flat natural sheet, m
  Vec3 gravity = Vec3::Zero();    // acceleration, m/s^2
  double velocity_damping = 0.0;  // D, 1/s: every particle feels -D m v

  // Calls f(set) for every element set, in a fixed order: the order of every sum over elements
  // (forces, energies, Hessians), so results are the same bit for bit. Registering a new element
  // kind is one more line here (docs/architecture.md, "Adding an element kind").
  template <typename F>
  void for_each_set(F&& f) const {
    f(springs);
    f(added_springs);
    f(bending);
    f(hinges);
    f(membrane_triangles);
    f(shell_triangles);
    f(table);
    f(self_contact);
  }
  template <typename F>
  void for_each_set(F&& f) {
    f(springs);
    f(added_springs);
    f(bending);
    f(hinges);
    f(membrane_triangles);
    f(shell_triangles);
    f(table);
    f(self_contact);
  }

  // Calls f(set, other's set of the same kind) for every element set, in the same order.
  template <typename F>
  void for_each_set_with(const Model& other, F&& f) {
    f(springs, other.springs);
    f(added_springs, other.added_springs);
    f(bending, other.bending);
    f(hinges, other.hinges);
    f(membrane_triangles, other.membrane_triangles);
    f(shell_triangles, other.shell_triangles);
    f(table, other.table);
    f(self_contact, other.self_contact);
  }

  int num_particles() const { return static_cast<int>(mass.size()); }
  bool pinned(int p) const { return inv_mass[p] == 0.0; }
  // Pins (fixes) particle p: it keeps its position and takes no force.
  void pin(int p) { inv_mass[p] = 0.0; }
  // Frees particle p.
  void unpin(int p) { inv_mass[p] = 1.0 / mass[p]; }
  // Appends a free particle of mass m (> 0) at paper position x; returns its index.
  int add_particle(double m, const Vec3& x);
};

// How far Newton's step along negative curvature may move a particle (m): on a lattice, the mean
// rest length of the springs (as the lattice's examples were validated with); on a continuum
// sheet (no springs), the sheet's larger side, because its graded elements say nothing of the
// scale a sheet buckles at (docs/solver.md, "Escaping saddles"). 1 where neither gives a length.
double saddle_escape_length(const Model& model);

struct State {
  Points x;           // positions, m
  Points v;           // velocities, m/s
  double time = 0.0;  // s

  // The state at rest in the model's reference configuration.
  static State at_rest(const Model& model);
};

}  // namespace membra
