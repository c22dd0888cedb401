#pragma once
// Gaussian curvature by angle defect (the paper's equation 6): at an interior vertex
// 2 pi - sum of the incident triangle angles, at a boundary vertex pi - sum (the boundary's
// turning, which makes Gauss-Bonnet exact: sum of all = 2 pi chi). The density divides the
// integrated value by the vertex's mixed Voronoi area (docs/measures.md says why not a third of
// the incident triangle areas, which is also given).
#include <string>
#include <vector>

#include "membra/core/vec.hpp"
#include "membra/geometry/grid_sheet.hpp"
#include "membra/geometry/triangulation.hpp"

namespace membra {

struct GaussianCurvature {
  std::vector<double> angle_defect;      // integrated curvature per vertex, rad (dimensionless)
  std::vector<double> area;              // mixed Voronoi area (Meyer et al. 2003), m^2
  std::vector<double> area_barycentric;  // a third of the incident triangles' area, m^2
  std::vector<double> density;  // angle_defect / area at interior vertices, 1/m^2; 0 elsewhere
  std::vector<bool> interior;   // false on the boundary (and for unused vertices)
  double total = 0.0;           // sum over interior vertices, rad
  double positive = 0.0;        // sum of the positive interior defects, rad
  double negative = 0.0;        // sum of the negative interior defects (<= 0), rad
  double boundary = 0.0;        // sum of the boundary vertices' pi - sum, rad
  double min_density = 0.0, max_density = 0.0;  // over interior vertices, 1/m^2
};

// Angle defects of the triangle mesh (triangles index the columns of x).
GaussianCurvature gaussian_curvature(const Points& x, const std::vector<Triangle>& triangles);

// Replaces the densities of a grid sheet's mesh by area-weighted averages over each vertex's
// 3 x 3 neighbourhood (weights 4, 2, 1: a bilinear filter). membra's grid alternates vertices of
// valence 8 and 4, and single-vertex defects alternate with them (on z = xy: -2 and 0 where
// K = -1); the filter removes the alternation and keeps smooth fields. `positive` and
// `negative` are recomputed from the smoothed densities; `total` stays the exact raw sum.
void smooth_density_on_grid(const GridSheet& grid, GaussianCurvature& k);

// Makes `density` (one value per vertex, 0 off the interior) k's density, with min/max density
// and the positive and negative parts (density x area, by sign) following it over the interior
// vertices: what every smoothing of the density ends with. `total` stays the raw sum.
void set_smoothed_density(GaussianCurvature& k, std::vector<double> density);

// Form class from the interior defects (rule in docs/measures.md): "developable" when
// positive + |negative| < threshold; otherwise "synclastic" when positive >= 2 |negative|,
// "anticlastic" when |negative| >= 2 positive, else "folded".
std::string classify_form(const GaussianCurvature& k, double threshold = 0.05);

// Mean curvature magnitude per vertex from the cotangent Laplacian, |H| = |L x| / (2 A) with A
// the mixed Voronoi area, 1/m,
// at interior vertices (0 on the boundary).
std::vector<double> mean_curvature(const Points& x, const std::vector<Triangle>& triangles);

}  // namespace membra
