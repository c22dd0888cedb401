#pragma once
// How far a simulated form is from a target surface, after moving the form rigidly onto it
// (iterative closest points: Kabsch's rotation to start, then point-to-plane steps, Chen &
// Medioni 1992, which also settle turns within the surface that point-to-point ICP leaves).
// Distances are measured both ways (form to target, target to form) so that a form that covers only
// part of the target is not counted as a match.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "membra/design/target_surface.hpp"
#include "membra/geometry/rigid_fit.hpp"

namespace membra {

struct ShapeError {
  double rms = 0.0;                   // m: root mean square over both directions' vertex distances
  double max = 0.0;                   // m: the largest of them
  RigidMotion motion;                 // form -> target
  std::vector<double> form_distance;  // m, per form vertex, after the motion
};

// Distance from point p to the mesh (exact point-triangle distance over the triangles around
// the nearest vertices). `tree` is built by the caller once per mesh.
class MeshDistance {
 public:
  MeshDistance(const Points& x, const std::vector<Triangle>& triangles);
  ~MeshDistance();
  MeshDistance(const MeshDistance&) = delete;
  MeshDistance& operator=(const MeshDistance&) = delete;
  // The distance from p to the mesh, the closest point and the unit normal of its triangle.
  double distance(const Vec3& p, Vec3* closest = nullptr, Vec3* normal = nullptr) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Aligns `form` to `target` rigidly (both orientations of the form tried: a dome and a bowl are
// the same shape turned over) and measures the remaining distances.
ShapeError compare_shapes(const Points& form, const std::vector<Triangle>& form_triangles,
                          const TargetSurface& target, int iterations = 100);

}  // namespace membra
