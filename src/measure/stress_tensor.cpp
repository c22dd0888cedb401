#include "membra/measure/stress_tensor.hpp"

#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>

namespace membra {

NodeStress node_stress(const GridSheet& g, const Model& model, const Points& x, double thickness) {
  const int n = model.num_particles();
  NodeStress out;
  std::vector<Eigen::Matrix3d>& sigma = out.sigma;
  sigma.assign(static_cast<size_t>(n), Eigen::Matrix3d::Zero());
  out.normal = Points::Zero(3, n);
  std::vector<double>& area = out.area;
  area.assign(static_cast<size_t>(n), 0.0);
  for (int j = 0; j + 1 < g.ny(); ++j)
    for (int i = 0; i + 1 < g.nx(); ++i) {
      if (!g.cell_active(i, j)) continue;
      const int p00 = g.particle(i, j), p10 = g.particle(i + 1, j), p01 = g.particle(i, j + 1),
                p11 = g.particle(i + 1, j + 1);
      // A quadrilateral's area is half the cross product of its diagonals.
      const Vec3 c = 0.5 * (x.col(p11) - x.col(p00)).cross(x.col(p01) - x.col(p10));
      const double a = c.norm();
      for (int p : {p00, p10, p01, p11}) area[p] += 0.25 * a, out.normal.col(p) += c;
    }
  // Every axial element's force (the springs'; element_set.hpp's read-out).
  model.for_each_set([&](const auto& set) {
    for (int s = 0; s < set.size(); ++s) {
      const ElementStress e = set.stress(s, x, thickness);
      if (!e.axial) continue;
      const auto p = set.ids(s);
      const Vec3 d = x.col(p[1]) - x.col(p[0]);
      const double l = d.norm();
      if (!(l > 0.0)) continue;
      const Eigen::Matrix3d half = 0.5 * e.force / l * d * d.transpose();  // 1/2 f l n n^T
      sigma[p[0]] += half;
      sigma[p[1]] += half;
    }
  });
  for (int p = 0; p < n; ++p) {
    sigma[p] =
        area[p] > 0.0 ? Eigen::Matrix3d(sigma[p] / (area[p] * thickness)) : Eigen::Matrix3d::Zero();
    const double len = out.normal.col(p).norm();
    out.normal.col(p) = len > 0.0 ? Vec3(out.normal.col(p) / len) : Vec3(0.0, 0.0, 1.0);
  }
  return out;
}

NodeStress smoothed(const NodeStress& s, const Model& model, double radius) {
  const int n = model.num_particles();
  // Bucket particles by paper position so each looks only at its neighbourhood.
  const Points& r = model.reference;
  const Vec2 lo = r.topRows<2>().rowwise().minCoeff();
  auto cell = [&](const Vec2& p) {
    return std::pair<long, long>(static_cast<long>((p.x() - lo.x()) / radius),
                                 static_cast<long>((p.y() - lo.y()) / radius));
  };
  std::map<std::pair<long, long>, std::vector<int>> buckets;
  for (int p = 0; p < n; ++p) buckets[cell(r.col(p).head<2>())].push_back(p);
  NodeStress out = s;
  for (int p = 0; p < n; ++p) {
    const Vec2 x = r.col(p).head<2>();
    const auto [ci, cj] = cell(x);
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double weight = 0.0;
    for (long di = -1; di <= 1; ++di)
      for (long dj = -1; dj <= 1; ++dj) {
        const auto it = buckets.find({ci + di, cj + dj});
        if (it == buckets.end()) continue;
        for (int q : it->second)
          if ((r.col(q).head<2>() - x).norm() <= radius) {
            sum += s.area[q] * s.sigma[q];
            weight += s.area[q];
          }
      }
    if (weight > 0.0) out.sigma[p] = sum / weight;
  }
  return out;
}

Eigen::Vector2d NodeStress::principal(int p) const {
  // Restrict the tensor to the tangent plane: the normal direction carries no membrane stress.
  const Vec3 nrm = normal.col(p);
  const Vec3 helper = std::abs(nrm.x()) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 t1 = nrm.cross(helper).normalized(), t2 = nrm.cross(t1);
  Eigen::Matrix<double, 3, 2> basis;
  basis << t1, t2;
  const Eigen::Matrix2d s2 = basis.transpose() * sigma[p] * basis;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s2, Eigen::EigenvaluesOnly);
  return es.eigenvalues();
}

std::vector<double> max_principal_stress(const NodeStress& s) {
  std::vector<double> out(s.sigma.size());
  for (size_t p = 0; p < out.size(); ++p) out[p] = s.principal(static_cast<int>(p))(1);
  return out;
}

}  // namespace membra
