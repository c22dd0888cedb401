#pragma once
// The shape objective of inverse design's second stage: the weighted mean squared distance of
// each particle from its own point on the target (correspondences fixed, e.g. by the target's
// flattening), after the rigid motion that makes it least (Kabsch's closed form, proper
// rotations only). The motion is the optimum for the positions, so by the envelope theorem the
// objective's gradient in the positions is that of the distance at this motion: no iterative
// closest points inside the optimisation loop, and the gradient is orthogonal to rigid motions.
#include <Eigen/Core>

#include "membra/core/vec.hpp"
#include "membra/design/shape_distance.hpp"

namespace membra {

struct Correspondence {
  Points target;           // m, the point each particle should reach (one column per particle)
  Eigen::VectorXd weight;  // per particle, >= 0, summing to 1 (e.g. its share of the area)
};

struct AlignedDistance {
  double value = 0.0;  // m^2: sum_i w_i |R x_i + t - T_i|^2
  RigidMotion motion;  // x -> target
  Points gradient;     // d value / d x, m
};

AlignedDistance aligned_distance(const Points& x, const Correspondence& c);

}  // namespace membra
