#pragma once
// Basic vector types shared by every layer.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace membra {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
// Particle data as a 3 x N matrix: column i is particle i (x, y, z), contiguous per particle.
using Points = Eigen::Matrix3Xd;

}  // namespace membra
