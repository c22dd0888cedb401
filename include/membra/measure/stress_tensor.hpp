#pragma once
// The membrane's stress tensor at every particle, from the virial of its springs:
// sigma_p = 1/(A_p t) sum_s 1/2 f_s l_s n_s n_s^T over the springs s at p (force f_s, tension > 0,
// current length l_s along unit n_s), with A_p a quarter of the current area of each cell around
// p. In a uniform state it equals the continuum (Cauchy) stress of the lattice exactly; near
// holes and cuts it is the average over the particle's quarter cells.
#include <vector>

#include <Eigen/Core>

#include "membra/geometry/grid_sheet.hpp"
#include "membra/model/model.hpp"

namespace membra {

struct NodeStress {
  std::vector<Eigen::Matrix3d> sigma;  // Pa, 3 x 3, in the sheet's tangent plane
  Points normal;                       // unit normal of the sheet at each particle
  std::vector<double> area;            // the particle's share of the sheet, m^2 (current)
  // In-plane principal stresses (Pa) of particle p, smaller first.
  Eigen::Vector2d principal(int p) const;
};

NodeStress node_stress(const GridSheet& grid, const Model& model, const Points& x,
                       double thickness);

// The area-weighted mean of the tensors of the particles within `radius` (paper distance, m) of
// each particle. On a grid, the edge of a round hole is a staircase whose corners overshoot and
// whose flat runs undershoot the smooth edge's stress; a mean over about 1.5 spacings recovers
// the stress of the edge it approximates (tested against Kirsch, docs/measures.md).
NodeStress smoothed(const NodeStress& s, const Model& model, double radius);

// Largest in-plane principal stress of each particle (Pa): the tension a crack there would feel.
std::vector<double> max_principal_stress(const NodeStress& s);

}  // namespace membra
