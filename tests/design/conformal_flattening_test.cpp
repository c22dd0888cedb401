// The conformal flattening of inverse design's first stage (design/conformal_flattening.hpp):
// exact on a plane, an isometry up to scale on a developable surface, and isotropic on a cap,
// where the projection onto the footprint is not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "membra/design/conformal_flattening.hpp"
#include "membra/design/target_surface.hpp"

namespace membra {
namespace {

TargetSurface target(const std::string& kind, double height, const std::string& formula = "") {
  TargetSpec s;
  s.kind = kind;
  s.size = 0.15;
  s.height = height;
  s.formula = formula;
  s.resolution = 21;
  return make_target(s);
}

// Per triangle, the singular values of the map from the flat triangle to the surface's.
std::vector<Eigen::Vector2d> stretches(const TargetSurface& t, const Eigen::Matrix2Xd& uv) {
  std::vector<Eigen::Vector2d> out;
  for (const Triangle& tri : t.triangles) {
    Eigen::Matrix2d flat;
    Eigen::Matrix<double, 3, 2> space;
    for (int j = 0; j < 2; ++j) {
      flat.col(j) = uv.col(tri[j + 1]) - uv.col(tri[0]);
      space.col(j) = t.x.col(tri[j + 1]) - t.x.col(tri[0]);
    }
    const Eigen::Matrix<double, 3, 2> jac = space * flat.inverse();
    out.push_back(Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>>(jac).singularValues());
  }
  return out;
}

TEST(ConformalFlattening, AFlatMeshKeepsItsPlace) {
  const TargetSurface t = target("height_field", 0.0, "0");
  const Eigen::Matrix2Xd uv = conformal_flattening(t.x, t.triangles);
  EXPECT_LT((uv - t.x.topRows<2>()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ConformalFlattening, ACylinderUnrollsByOneScale) {
  // Developable: the conformal map is an isometry up to one scale (the pins' chord against
  // their arc): every triangle stretched equally in both directions, by the same factor.
  const TargetSurface t = target("cylinder", 0.03);
  const auto s = stretches(t, conformal_flattening(t.x, t.triangles));
  double lo = 1e9, hi = 0.0;
  for (const auto& v : s) lo = std::min(lo, v.minCoeff()), hi = std::max(hi, v.maxCoeff());
  EXPECT_LT(hi / lo, 1.01);  // measured 1.00x
}

TEST(ConformalFlattening, ACapIsStretchedAlikeInEveryDirection) {
  // A spherical cap 150 mm across and 30 mm high: its slope at the rim is 43 degrees, so the
  // projection onto the footprint stretches the rim 1/cos = 1.37 times more across than along;
  // the conformal flattening stretches every triangle alike (within 3 %, measured 2.4 % on this
  // 21-vertex mesh), by a factor that grows towards the rim.
  const TargetSurface t = target("cap", 0.03);
  const auto conformal = stretches(t, conformal_flattening(t.x, t.triangles));
  const auto projected = stretches(t, t.x.topRows<2>());
  double worst_conformal = 0.0, worst_projected = 0.0;
  for (size_t k = 0; k < conformal.size(); ++k) {
    worst_conformal = std::max(worst_conformal, conformal[k][0] / conformal[k][1]);
    worst_projected = std::max(worst_projected, projected[k][0] / projected[k][1]);
  }
  std::printf("anisotropy: conformal %.4f, projected %.4f\n", worst_conformal, worst_projected);
  EXPECT_LT(worst_conformal, 1.03);
  EXPECT_GT(worst_projected, 1.25);
}

}  // namespace
}  // namespace membra
