// Positions carried from a coarser mesh of a sheet to a finer one (geometry/mesh_prolongation.hpp).
#include "membra/geometry/mesh_prolongation.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "membra/model/continuum_sheet.hpp"

namespace membra {
namespace mesh_prolongation {
namespace {

struct Meshed {
  Points reference;
  std::vector<Triangle> triangles;
};

// The continuum's CGAL mesh of a 200 x 100 mm sheet (a disk: its outline's chords differ from
// mesh to mesh) at max_edge.
Meshed meshed(double max_edge, bool disk) {
  ContinuumSpec spec;
  spec.width = 0.2, spec.height = 0.1, spec.disk = disk;
  spec.mesh.max_edge = max_edge;
  const PlanarMesh mesh = mesh_sheet(spec).mesh;
  Meshed m;
  m.reference = Points::Zero(3, static_cast<Eigen::Index>(mesh.vertices.size()));
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    m.reference.col(static_cast<Eigen::Index>(i)).head<2>() = mesh.vertices[i];
  for (const auto& t : mesh.triangles) m.triangles.emplace_back(t[0], t[1], t[2]);
  return m;
}

// An affine map of the sheet into space: linear interpolation carries it exactly (to round-off)
// to every fine vertex. On a disk too: its outline is sampled to the chord tolerance whatever
// max_edge, so both meshes share it (measured: 6e-17 m on both sheets).
TEST(MeshProlongation, CarriesAnAffineMapExactly) {
  Eigen::Matrix3d a;
  a << 1.3, 0.2, 0.0, -0.1, 0.9, 0.0, 0.4, 0.5, 1.0;
  const Vec3 b(0.01, -0.02, 0.03);
  for (bool disk : {false, true}) {
    const Meshed coarse = meshed(0.02, disk), fine = meshed(0.007, disk);
    const Points coarse_x = (a * coarse.reference).colwise() + b;
    const Points x = prolongate_on_mesh(coarse.reference, coarse.triangles, coarse_x,
                                        fine.reference, fine.triangles);
    const Points want = (a * fine.reference).colwise() + b;
    const double worst = (x - want).colwise().norm().maxCoeff();
    std::printf("affine map carried, %s: largest error %.3g m\n", disk ? "disk" : "rectangle",
                worst);
    EXPECT_LT(worst, 1e-12);
  }
}

// A square opened along its diagonal: the slit's two ends have a copy per lip (4, 5 beside 0, 2)
// at one natural-sheet point. Each copy takes its own lip's position, the lips here pulled apart
// along z; a point outside the coarse mesh takes its nearest triangle's, clamped to it.
TEST(MeshProlongation, EachLipOfASlitTakesItsOwnSide) {
  Points reference(3, 6);
  reference << 0, 1, 1, 0, 0, 1,  //
      0, 0, 1, 1, 0, 1,           //
      0, 0, 0, 0, 0, 0;
  const std::vector<Triangle> triangles = {Triangle(0, 1, 2), Triangle(4, 5, 3)};
  Points x = reference;
  x.row(2) << -0.1, -0.1, -0.1, 0.1, 0.1, 0.1;
  const Points carried = prolongate_on_mesh(reference, triangles, x, reference, triangles);
  EXPECT_LT((carried - x).cwiseAbs().maxCoeff(), 1e-15);
  // A fine vertex outside, with no triangle of its own: found at its point.
  Points outside(3, 1);
  outside << 2.0, 0.0, 0.0;
  const Points far = prolongate_on_mesh(reference, triangles, x, outside, {});
  EXPECT_TRUE(far.allFinite());
  EXPECT_NEAR(far(2, 0), -0.1, 1e-15);  // the lower triangle's corner (1, 0), the nearest
}

TEST(MeshProlongation, RefusesAnEmptyCoarseMesh) {
  EXPECT_THROW(
      (void)prolongate_on_mesh(Points::Zero(3, 1), {}, Points::Zero(3, 1), Points::Zero(3, 2), {}),
      std::invalid_argument);
}

}  // namespace
}  // namespace mesh_prolongation
}  // namespace membra
