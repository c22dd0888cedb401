#pragma once
// The constant model (masses, springs, loads) kept apart from the changing state (positions,
// velocities), like MuJoCo's mjModel / mjData. Protocol steps change the model between solves;
// solvers only change the state.
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/model/bending.hpp"
#include "membra/model/hinges.hpp"
#include "membra/model/springs.hpp"

namespace membra {

struct Model {
  std::vector<double> mass;      // kg, lumped
  std::vector<double> inv_mass;  // 1/kg; 0 means pinned
  Springs springs;
  Bending bending;                // bending elements; empty when the sheet has none
  Hinges hinges;                  // bilayer moments; empty unless resin was applied as a bilayer
  Points reference;               // paper position of each particle in the flat natural sheet, m
  Vec3 gravity = Vec3::Zero();    // acceleration, m/s^2
  double velocity_damping = 0.0;  // D, 1/s: every particle feels -D m v

  int num_particles() const { return static_cast<int>(mass.size()); }
  bool pinned(int p) const { return inv_mass[p] == 0.0; }
  // Pins (fixes) particle p: it keeps its position and takes no force.
  void pin(int p) { inv_mass[p] = 0.0; }
  // Frees particle p.
  void unpin(int p) { inv_mass[p] = 1.0 / mass[p]; }
  // Appends a free particle of mass m (> 0) at paper position x; returns its index.
  int add_particle(double m, const Vec3& x);
};

struct State {
  Points x;           // positions, m
  Points v;           // velocities, m/s
  double time = 0.0;  // s

  // The state at rest in the model's reference configuration.
  static State at_rest(const Model& model);
};

}  // namespace membra
