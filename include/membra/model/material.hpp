#pragma once
// Materials in SI units and their homogenization into lattice spring stiffnesses.
#include <optional>
#include <string>
#include <string_view>

#include "membra/model/membrane_law.hpp"

namespace membra {

// An isotropic thin sheet material.
struct Material {
  std::string name;
  double youngs_modulus = 0.0;  // E, Pa
  double thickness = 0.0;       // t, m
  double density = 0.0;         // rho, kg/m^3
  // The continuum sheet's law for this material (membrane_law.hpp); the lattice's springs are
  // linear whatever it says.
  MembraneLaw law = MembraneLaw::neo_hookean;
  // How the continuum membrane takes compression (membrane_law.hpp): relaxed = tension-field
  // theory, for relaxable laws; the resin's layer and the latex under it are never relaxed.
  Wrinkling wrinkling = Wrinkling::full;
};

// Natural-rubber latex: E 1.5 MPa, t 0.5 mm, rho 0.93 g/cm^3, incompressible neo-Hookean.
Material latex();
// Cured epoxy composite: E 2.5 GPa, t 0.5 mm, rho 1.2 g/cm^3, Saint Venant-Kirchhoff.
Material epoxy();
// A preset by name ("latex", "epoxy"), or nothing.
std::optional<Material> material_preset(std::string_view name);

// Spring stiffnesses (N/m) of the three lattice families.
struct LatticeStiffness {
  double stretch = 0.0;  // grid edges
  double shear = 0.0;    // each of the two cell diagonals
  double flex = 0.0;     // skip-one springs along the grid lines
};

// Stiffnesses whose continuum limit on a square grid is isotropic with membrane stiffness
// E*t and Poisson ratio 1/3 (docs/model.md, "Homogenization"). `flex_ratio` = k_flex / k_stretch (0
// = no flex springs). The grid spacing does not enter: a spring of stiffness k spanning a cell
// gives a membrane stiffness k whatever the cell size. Derivation: C11 = k + k_s + 4 k_f and C12 =
// C66 = k_s; isotropy needs k_s = (k + 4 k_f) / 2, then E t = 8 k_s / 3.
LatticeStiffness homogenize(const Material& m, double flex_ratio = 0.0);

// Membrane stiffness E*t (N/m) of a lattice whose stretch stiffness is k, for the same
// flex_ratio: the inverse of homogenize().
double membrane_stiffness_from_stretch(double k_stretch, double flex_ratio = 0.0);

// Plate bending stiffness D = E t^3 / (12 (1 - nu^2)) in N*m, for the lattice's nu = 1/3.
double bending_stiffness(const Material& m);

}  // namespace membra
