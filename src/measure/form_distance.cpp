#include "membra/measure/form_distance.hpp"

#include <stdexcept>

#include "membra/geometry/rigid_fit.hpp"

namespace membra {

double form_distance(const Points& a, const Points& b, bool align) {
  if (a.cols() != b.cols() || a.cols() == 0)
    throw std::invalid_argument("form_distance: the forms have different particle counts");
  const double n = static_cast<double>(a.cols());
  if (!align) return std::sqrt((a - b).colwise().squaredNorm().sum() / n);
  const Vec3 ca = a.rowwise().mean(), cb = b.rowwise().mean();
  const Points pa = a.colwise() - ca, pb = b.colwise() - cb;
  const Eigen::Matrix3d r = kabsch_rotation(pa * pb.transpose());
  return std::sqrt(((r * pa) - pb).colwise().squaredNorm().sum() / n);
}

}  // namespace membra
