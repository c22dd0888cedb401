#pragma once
// Membrane triangles: the continuum sheet's in-plane elasticity (docs/model.md, "The continuum
// shell"). A triangle (x0, x1, x2) stores W(I, J) x rest volume for each of its layers, with
// I = tr(G^-1 g) and J = det g / det G the invariants of C between its rest metric G and its
// current metric g = Ds^T Ds (Ds = [x1 - x0, x2 - x0], 3 x 2): the metric form of discrete
// shells, independent of how the triangle is turned. Two layers in parallel, as the lattice's
// composite: the latex, at rest in its natural shape (moving to the frame's shape while the
// release is undone, like the springs' rest lengths), and the resin, at rest in the shape it was
// impregnated in. The laws are membrane_law.hpp's; the Hessian is the exact derivative of the
// analytic gradient, by dual numbers.
#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/set_context.hpp"
#include "membra/model/membrane_law.hpp"

namespace membra {

// The cut rule of both triangle sets: a triangle goes when the cut crosses one of its edges.
bool triangle_severed(const CrossesCut& crosses, int a, int b, int c);

// A triangle's rest state for one layer: its metric inverted, 1 / det of the metric, its volume.
struct LayerRest {
  Eigen::Matrix2d metric_inverse = Eigen::Matrix2d::Identity();
  double inverse_det = 1.0;
  double volume = 0.0;  // m^3; 0: no such layer
  LawConstants law;
};

// Both triangle sets' growth rule: the growth of triangle (a, b, c) read from the field at its
// paper positions; and a share e of it applied to the triangle's natural and frame metrics by the
// stretch P = E^-1 A^e E it makes in the edge basis E (a metric G grows to P^T G P). Returns
// det P, the growth of the triangle's area.
LocalGrowth triangle_growth(const GrowthField& field, const Points& paper, int a, int b, int c);
double grow_metrics(const LocalGrowth& g, const Points& paper, int a, int b, int c, double exponent,
                    Eigen::Matrix2d& natural, Eigen::Matrix2d& frame);

// The growth of each triangle of a set whose elements start with their three corners.
template <size_t N>
std::vector<LocalGrowth> triangles_growth(const std::vector<std::array<int, N>>& v,
                                          const GrowthField& field, const Points& paper) {
  std::vector<LocalGrowth> g;
  g.reserve(v.size());
  for (const auto& p : v) g.push_back(triangle_growth(field, paper, p[0], p[1], p[2]));
  return g;
}

struct MembraneTriangles {
  static constexpr int kArity = 3;
  static constexpr std::string_view kName = "membrane";
  static constexpr EnergyKind kEnergy = EnergyKind::stretching;

  std::vector<std::array<int, 3>> v;  // counter-clockwise on the natural sheet
  std::vector<LayerRest> latex, resin;
  // Material state: the latex's metric in the natural sheet and when the release began, and its
  // natural thickness (the stress read-out's, as the lattice's).
  std::vector<Eigen::Matrix2d> natural_metric, frame_metric;
  std::vector<double> thickness;

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 3> ids(int i) const { return v[static_cast<size_t>(i)]; }
  bool active(int) const { return true; }
  // Appends a triangle of latex at rest at the natural positions p0, p1, p2 (m) with the law's
  // constants and thickness t (m). Throws std::invalid_argument for a degenerate triangle.
  void add(const std::array<int, 3>& ids, const Vec3& p0, const Vec3& p1, const Vec3& p2,
           const LawConstants& law, double t);
  void filter(const std::vector<bool>& keep);

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 9, 9> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  // The membrane force tensor's largest eigenvalue over the natural thickness (Pa, tension > 0),
  // both layers together: comparable with the springs' force / (width x thickness).
  ElementStress stress(int i, const Points& x, double thickness) const;
  // The membrane force tensor over the natural thickness (Pa, 3 x 3 symmetric, in the triangle's
  // plane): the triangle's (constant) stress for measures that need its directions. Zero for a
  // triangle collapsed to a line.
  Eigen::Matrix3d stress_tensor(int i, const Points& x) const;

  // Composite rule: the latex's rest metric moves from the frame's (level 1) to the natural one
  // (level 0) along the release; the resin keeps its own.
  void update(const ReleaseLevel& release);
  void begin_release(const Points& x);
  // Resin rule: a triangle whose centroid lies inside the pattern takes a resin layer at rest in
  // its current shape (the resin material's law and E, nu 1/3, and the resin's thickness).
  int impregnate(const Impregnation& at);
  bool severed(int i, const CrossesCut& crosses) const {
    return triangle_severed(crosses, v[static_cast<size_t>(i)][0], v[static_cast<size_t>(i)][1],
                            v[static_cast<size_t>(i)][2]);
  }
  // Triangles whose three particles survive a rebuild, with their state.
  void carry(const MembraneTriangles& old, const Rebuild& r);
  // Growth rule: the growth read at the centroid (blended by the share of the outline inside a
  // grow region) stretches the latex's natural and frame metrics, G -> P^T G P with P the
  // stretch in the triangle's edge basis; the resin keeps its metric.
  std::vector<LocalGrowth> growth(const GrowthField& field, const Points& paper) const {
    return triangles_growth(v, field, paper);
  }
  void grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
            const ReleaseLevel& release);
  // The design's resin maps do not place resin on triangles yet.
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
};

// The metric Ds^T Ds of triangle (x0, x1, x2) in its edge basis (m^2).
Eigen::Matrix2d triangle_metric(const Vec3& x0, const Vec3& x1, const Vec3& x2);

// The latex's rest metric along the release: the frame's at level 1, the natural one at 0 (the
// natural one before the release begins), as the springs' rest lengths move.
Eigen::Matrix2d released_metric(const Eigen::Matrix2d& natural, const Eigen::Matrix2d& frame,
                                const ReleaseLevel& release);

// Does the impregnation's pattern cover the triangle of particles a, b, c (its centroid, at the
// positions it was impregnated in)? With meshes that follow the pattern, a triangle is in or out.
bool pattern_covers(const Impregnation& at, int a, int b, int c);

}  // namespace membra
