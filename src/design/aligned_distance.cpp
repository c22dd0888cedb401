#include "membra/design/aligned_distance.hpp"

#include "membra/geometry/rigid_fit.hpp"

namespace membra {

AlignedDistance aligned_distance(const Points& x, const Correspondence& c) {
  const Eigen::Index n = x.cols();
  // The optimal translation matches weighted centroids (rigid_fit divides by the weights' sum):
  // otherwise the gradient (envelope theorem) would be wrong.
  AlignedDistance a;
  a.motion = rigid_fit(x, c.target, c.weight);
  a.gradient.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3 r = a.motion.apply(x.col(i)) - c.target.col(i);
    a.value += c.weight[i] * r.squaredNorm();
    a.gradient.col(i) = 2.0 * c.weight[i] * (a.motion.rotation.transpose() * r);
  }
  return a;
}

}  // namespace membra
