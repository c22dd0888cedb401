#include "membra/model/elements/hinge_kernel.hpp"

#include <unsupported/Eigen/AutoDiff>

#include "membra/model/psd_projection.hpp"

namespace membra {

HingeHessian hinge_hessian(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                           double moment, bool project) {
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;
  using V = Eigen::Matrix<Dual, 3, 1>;
  const std::array<const Vec3*, 4> p = {&x0, &x1, &x2, &x3};
  std::array<V, 4> x;
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c)
      x[static_cast<size_t>(k)][c] = Dual((*p[static_cast<size_t>(k)])[c], 12, 3 * k + c);
  const std::array<V, 4> g = hinge_theta_gradient(x);
  HingeHessian h;
  for (int r = 0; r < 12; ++r)
    h.row(r) = g[static_cast<size_t>(r / 3)][r % 3].derivatives().transpose();
  const HingeHessian sym = (0.5 * moment) * (h + h.transpose());  // not in place: aliasing
  return project ? project_psd(sym) : sym;
}

}  // namespace membra
