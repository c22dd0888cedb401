#pragma once
// Form from a Gaussian-curvature map (the paper's experiment 6). A flat sheet whose lengths are
// scaled by e^u, u a function over it, has the metric e^{2u}(dx^2 + dy^2), whose Gaussian
// curvature is K = -e^{-2u} (u_xx + u_yy). So rest lengths that carry a wanted map K(x, y) follow
// from the Liouville equation
//     Laplacian(u) = -K e^{2u},   u = 0 on the sheet's edge (the edge keeps its length),
// solved on the grid or the mesh; the released sheet then takes a form with (nearly) that
// curvature, to the degree that bending lets it. docs/curvature_map.md has the method and its
// limits.
#include <string>
#include <vector>

#include "membra/model/elements/set_context.hpp"
#include "membra/model/sheet.hpp"

namespace membra {

struct ConformalOptions {
  int continuation_steps = 8;  // K is ramped from 0 in this many steps (halved on trouble)
  int max_newton = 25;         // Newton iterations per step
  double tolerance = 1e-10;    // on max |Laplacian(u) + K e^{2u}| x h^2 (on a mesh: x the
                               // area lumped to the particle)
};

struct ConformalFactor {
  std::vector<double> u;  // per particle
  double reached = 0.0;   // share of the map solved for: 1 when the whole map is reachable
  std::string message;    // why not, when reached < 1
};

// Particles on the sheet's edge: those missing one of their four grid neighbours.
std::vector<bool> edge_particles(const GridSheet& grid);
// ... or, on a continuum sheet, the mesh's boundary vertices (outline, holes and slits).
std::vector<bool> edge_particles(const Sheet& sheet);

// Solves the Liouville equation for the target curvature K (1/m^2, per particle) with the 5-point
// Laplacian on the sheet's grid, or on a continuum sheet with the mesh's linear elements
// (cotangent weights, a third of each triangle's area lumped to its corners). Ramps K from 0 so the
// solution stays on the branch connected to the flat sheet; where that branch ends (the map asks
// for more curvature than a sheet with this edge can carry, e.g. more than a hemisphere for
// constant K > 0 on a disk) it stops and reports the share reached.
ConformalFactor conformal_factor(const Sheet& sheet, const std::vector<double>& K,
                                 const ConformalOptions& options = {});

// The growth that carries the factor: isotropic, e^u averaged over the element's particles in
// the exponent (a spring grows by e^{(u_a + u_b)/2}).
class ConformalGrowth final : public GrowthField {
 public:
  explicit ConformalGrowth(std::vector<double> u) : u_(std::move(u)) {}
  LocalGrowth at(std::span<const int> ids, std::span<const Vec2> paper,
                 std::string_view group) const override;

 private:
  std::vector<double> u_;  // per particle
};

// How well a measured curvature (1/m^2, per particle) matches the target over the interior: the
// particles at least `margin` (m, paper distance) from the edge.
struct CurvatureMatch {
  int interior = 0;                               // particles compared
  double correlation = 0.0;                       // Pearson's r (0 when either side is constant)
  double rms_error = 0.0;                         // 1/m^2
  double relative_rms_error = 0.0;                // rms_error / rms(target)
  double mean_target = 0.0, mean_measured = 0.0;  // 1/m^2
};
CurvatureMatch match_curvature(const Sheet& sheet, const std::vector<double>& target,
                               const std::vector<double>& measured, double margin);

}  // namespace membra
