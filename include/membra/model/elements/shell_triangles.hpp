#pragma once
// Shell triangles: the continuum sheet's bending as a Kirchhoff plate per triangle, its
// curvature read as a boundary integral (docs/model.md, "Bending"). Each edge's outward slope,
// measured from the triangle's plane, comes from one surface gradient that both triangles sharing
// the edge agree on: the mean of the quadratics fitted to each triangle and its three neighbours,
// at the edge's midpoint. So the curvature integrated over any patch telescopes to its rim (the
// weak patch test), and it is exact on any quadratic surface. II = (1/A) sum_k l_k s_k n_k n_k^T
// on the natural sheet, n_k the edge's outward conormal, s_k its slope. Each layer stores
//   A (D/2) [nu tr(M)^2 + (1 - nu) tr(M^2)],   M = G^-1 II,
// G and A its rest metric and area, D and nu its plate: Kirchhoff's energy density
// (D/2)(4H^2 - 2(1 - nu)K), a positive semi-definite form, so the energy is bounded below. Two
// layers as the membrane's: the latex (rest metric following the release) and, where the pattern
// covers the triangle, the resin at rest in its impregnated shape. Edge by edge:
//  - shared (a neighbour of like plate): the mean gradient of the well-posed fits of the two,
//    or, where neither is, of their two planes;
//  - free (the rim, or a much softer neighbour): no moment crosses it, its slope is the one that
//    minimizes the triangle's energy;
//  - clamped (a much stiffer neighbour, the latex against resin): the stiff plate's plane is the
//    edge's slope, so the kink goes to the latex, as plates in series share it.
// A coat on one face (a bilayer) gives a triangle a rest curvature, the second fundamental form
// both its layers are at rest in: Timoshenko's curvature of the misfit between the coat and the
// latex (bilayer.hpp), grown with the release as the lattice's hinge moments are; the energy is
// then the plates' form of II - II0 (docs/model.md, "Bilayer coats").
// The gradient is analytic and the Hessian exact, in closed form.
#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/lazy_table.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// One layer's bending state: rest metric inverted, rest area (m^2), its plate's D (N m) and nu.
struct PlateLayer {
  Eigen::Matrix2d metric_inverse = Eigen::Matrix2d::Identity();
  double area = 0.0;  // 0: no such layer
  double d = 0.0, nu = 0.0;
};

// What a triangle's curvature reading takes from the natural sheet, fixed when the mesh is made.
struct ShellReference {
  Eigen::Matrix<double, 2, 3> gradient =
      Eigen::Matrix<double, 2, 3>::Zero();  // of its corners' hat functions (1/m)
  std::array<Vec2, 3> conormal{};           // edge k's outward unit conormal
  // The edges' slopes s to II in the edge coordinates (II11, II12, II22): column k is
  // (l_k / A) (a^2, a b, b^2), (a, b) the conormal's dot products with the two edges from corner 0.
  Eigen::Matrix3d curvature = Eigen::Matrix3d::Zero();
  // The fitted quadratic's derivative along edge k's conormal at its midpoint, a combination of
  // the triangle's six points (corners, then far corners).
  std::array<Eigen::Matrix<double, 1, 6>, 3> slope{};
  double quality = 0.0;  // the fit's smallest singular value; 0 where it is not posed
};

struct ShellTriangles {
  static constexpr int kArity = 12;
  static constexpr std::string_view kName = "shell_triangles";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  // x0, x1, x2 (counter-clockwise on the natural sheet); in slot 3 + k the far corner across the
  // edge opposite corner k; in slots 6 + 2k and 7 + 2k that neighbour's own far corners across its
  // other two edges (its fit's points). An absent point's slot holds a corner as a placeholder,
  // never read (its edge is free, or that neighbour's fit does not count).
  std::vector<std::array<int, 12>> v;
  std::vector<std::array<int, 3>> neighbour;  // the triangle across each edge, -1 on the rim
  std::vector<ShellReference> reference;
  std::vector<PlateLayer> latex, resin;
  // Material state: the latex's metric on the natural sheet and when the release began.
  std::vector<Eigen::Matrix2d> natural_metric, frame_metric;
  // A coat's rest curvature once released, II0 in the edge coordinates (II11, II12, II22; 1/m
  // times the metric), and the share of it the release has reached (0 before the release).
  std::vector<Eigen::Vector3d> coat_curvature;
  double coat_share = 0.0;

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 12> ids(int i) const { return v[static_cast<size_t>(i)]; }
  bool active(int i) const { return latex[static_cast<size_t>(i)].d > 0.0; }
  // A plate of stiffness d and Poisson ratio nu on every triangle of a mesh of counter-clockwise
  // triangles at rest at `reference` (m). Throws std::invalid_argument for a degenerate triangle
  // or a negative d.
  void add_mesh(const std::vector<std::array<int, 3>>& triangles, const Points& reference, double d,
                double nu);
  void filter(const std::vector<bool>& keep);
  // The plate stiffness of triangle i, both layers (what the edges' normals are weighted by).
  double plate(int i) const;

  // Kernel.
  double energy(int i, const Points& x) const;
  void add_forces(const Points& x, const Points* v, int begin, int end, Points& f) const;
  Eigen::Matrix<double, 36, 36> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  ElementStress stress(int, const Points&, double) const { return {}; }  // no in-plane stress

  // The latex's rest metric follows the release as the membrane's does; the resin keeps its own.
  void update(const ReleaseLevel& release);
  void begin_release(const Points& x);
  // Resin rule: a triangle whose centroid lies inside the pattern takes the resin's plate (its
  // material's D, nu 1/3) with the metric of its current shape (a later coat replaces it). A coat
  // on one face (at.bilayer) also sets its rest curvature: -side T eps / h in the plane, eps the
  // misfit strain I - V^-1 of the stretch V at impregnation, with the coat on the convex side.
  int impregnate(const Impregnation& at);
  bool severed(int i, const CrossesCut& crosses) const {
    return triangle_severed(crosses, v[static_cast<size_t>(i)][0], v[static_cast<size_t>(i)][1],
                            v[static_cast<size_t>(i)][2]);
  }
  void carry(const ShellTriangles& old, const Rebuild& r);
  // A slit's rule (continuum_slit.hpp): every triangle's corners as given (the same triangles,
  // particles along the slit now one per side); a neighbour that no longer shares an edge's two
  // corners leaves that edge free.
  void split_corners(const std::vector<std::array<int, 3>>& corners);
  // Growth rule: the latex's metric grows as the membrane's (triangle_growth); its plate follows.
  std::vector<LocalGrowth> growth(const GrowthField& field, const Points& paper) const {
    return triangles_growth(v, field, paper);
  }
  void grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
            const ReleaseLevel& release);
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
  // How each edge's slope is read: shared with a neighbour of like plate, free (the rim, or a
  // neighbour of less than kSofter of this triangle's plate: a resin triangle's edge against
  // latex), or clamped to a neighbour of more than 1/kSofter of it (the latex against resin).
  enum class Edge { shared, free, clamped };
  static constexpr double kSofter = 0.5;
  std::array<Edge, 3> edges(int i) const;
  std::array<bool, 3> free_edges(int i) const;
  // A triangle's own fit counts where it is posed and none of its edges meets another material.
  bool fit_counts(int i) const;

  // How triangle i reads its curvature (shell_triangles.cpp): each edge's slope s_k = t . w_k,
  // t its unit normal and w_k = sum_a coef(k, a) x_a (the agreed gradient along the conormal);
  // e = map s + shift is II - II0 in edge coordinates, free edges' slopes eliminated; energy
  // e^T form e.
  struct Plan {
    std::array<Edge, 3> edges{};
    Eigen::Matrix<double, 3, 12> coef = Eigen::Matrix<double, 3, 12>::Zero();
    Eigen::Matrix3d map = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d form = Eigen::Matrix3d::Zero();
    // -II0 and what the free edges' slopes add towards it (zero without a coat).
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  };
  Plan plan(int i) const;
  // plan(i) as built once for every triangle after the last change of the rest state (the
  // kernels read it on every pass). Call invalidate() after writing the members above directly;
  // the member functions that change them do.
  const Plan& planned(int i) const;
  void invalidate() { plans_.clear(); }

 private:
  LazyTable<Plan> plans_;

  // Slots 6..11 from each neighbour's far corners (after the mesh, a filter, a carry or a split).
  void link_neighbours();
  // The slot of triangle i's stencil that holds particle id, or -1.
  int slot_of(int i, int id) const;
  // Adds `weight` times neighbour o's fit slope at its edge facing i into row k of coef (false
  // where a point of that fit is not in i's stencil).
  bool add_neighbour_slope(int i, int k, int o, double weight, Plan& pl) const;
};

}  // namespace membra
