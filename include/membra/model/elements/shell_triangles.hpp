#pragma once
// Shell triangles: the continuum sheet's bending as a Kirchhoff plate per triangle, its
// curvature read from a quadratic fitted to the triangle and its three neighbours (rotation-free
// shell triangles; docs/model.md, "Bending"). Triangle (x0, x1, x2) with, across the edge
// opposite corner k, the neighbour's far corner o_k: the six particles of its stencil. The
// heights of the far corners over the face's plane fix the quadratic through the corners
// (height 0) and them, whose Hessian in the edge coordinates is the second fundamental form II
// (exact for a quadratic surface wherever the fit is well posed, up to a weak pull towards the
// mid-edge normals' estimate that keeps a degenerate fit bounded).
// Each layer stores
//   A (D/2) [nu tr(M)^2 + (1 - nu) tr(M^2)],   M = G^-1 II,
// G and A its rest metric and area, D and nu its plate: Kirchhoff's energy density
// (D/2)(4H^2 - 2(1 - nu)K), a positive semi-definite form in M, so the energy is bounded below
// on any configuration (unlike a Gaussian-curvature term added to dihedral hinges). A free edge
// (the rim, or a resin triangle's edge against latex) meets no height: no moment crosses it
// instead, so across a resin edge the kink is left to the latex, as plates in series share it. Two
// layers as the membrane's: the latex (rest metric following the release) and, where the pattern
// covers the triangle, the resin at rest in its impregnated shape. The gradient and Hessian are
// exact, by dual numbers.
#include <array>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "membra/model/elements/element_set.hpp"
#include "membra/model/elements/membrane_triangles.hpp"
#include "membra/model/elements/set_context.hpp"

namespace membra {

// One layer's bending state: rest metric inverted, rest area (m^2), its plate's D (N m) and nu.
struct PlateLayer {
  Eigen::Matrix2d metric_inverse = Eigen::Matrix2d::Identity();
  double area = 0.0;  // 0: no such layer
  double d = 0.0, nu = 0.0;
};

struct ShellScalars;  // shell_triangles.cpp: a triangle's six scalars and their derivatives

struct ShellTriangles {
  static constexpr int kArity = 6;
  static constexpr std::string_view kName = "shell_triangles";
  static constexpr EnergyKind kEnergy = EnergyKind::bending;

  // x0, x1, x2 (counter-clockwise on the natural sheet), then the far corner across the edge
  // opposite each (the triangle's own corner k where that edge is on the rim: see `neighbour`).
  std::vector<std::array<int, 6>> v;
  std::vector<std::array<int, 3>> neighbour;  // the triangle across each edge, -1 on the rim
  // Each far corner's row of the curvature fit (shell_triangles.cpp), from the natural sheet.
  std::vector<std::array<Eigen::Vector3d, 3>> fit;
  std::vector<PlateLayer> latex, resin;
  // Material state: the latex's metric on the natural sheet and when the release began.
  std::vector<Eigen::Matrix2d> natural_metric, frame_metric;

  int size() const { return static_cast<int>(v.size()); }
  std::array<int, 6> ids(int i) const { return v[static_cast<size_t>(i)]; }
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
  Eigen::Matrix<double, 18, 18> hessian(int i, const Points& x, bool project) const;
  void add_stiffness_estimate(const Points& x, std::vector<double>& diag) const;
  ElementStress stress(int, const Points&, double) const { return {}; }  // no in-plane stress

  // The latex's rest metric follows the release as the membrane's does; the resin keeps its own.
  void update(const ReleaseLevel& release);
  void begin_release(const Points& x);
  // Resin rule: a triangle whose centroid lies inside the pattern takes the resin's plate (its
  // material's D, nu 1/3) with the metric of its current shape (a later coat replaces it).
  int impregnate(const Impregnation& at);
  bool severed(int i, const CrossesCut& crosses) const {
    return triangle_severed(crosses, v[static_cast<size_t>(i)][0], v[static_cast<size_t>(i)][1],
                            v[static_cast<size_t>(i)][2]);
  }
  void carry(const ShellTriangles& old, const Rebuild& r);
  // Growth rule: the latex's metric grows as the membrane's (triangle_growth); its plate follows.
  std::vector<LocalGrowth> growth(const GrowthField& field, const Points& paper) const {
    return triangles_growth(v, field, paper);
  }
  void grow(const std::vector<LocalGrowth>& g, const Points& paper, double exponent,
            const ReleaseLevel& release);
  ResinFootprint footprint(int, const Points&) const { return {}; }
  void set_resin_fraction(int, double, const ReleaseLevel&) {}
  double resin_rate(int, const Points&, const Points&, const ReleaseLevel&) const { return 0.0; }
  // The edges whose far corner's height is free: on the rim, or across from a neighbour of less
  // than kSofter of this triangle's plate (a resin triangle next to latex).
  static constexpr double kSofter = 0.5;
  std::array<bool, 3> free_edges(int i) const;

  // How triangle i reads its curvature H = (H11, H12, H22) (edge coordinates) from its six
  // geometric scalars g (far corners' heights, mid-edge readings): H = map g, and its energy
  // H^T form H (shell_triangles.cpp).
  struct Plan {
    std::array<bool, 3> free{};
    Eigen::Matrix<double, 3, 6> map;
    Eigen::Matrix3d form;
  };
  Plan plan(int i) const;

 private:
  void scalars(int i, const Points& x, const Plan& pl, bool second, ShellScalars& out) const;
};

}  // namespace membra
