#include "membra/design/shape_distance.hpp"

#include <Eigen/Geometry>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace membra {
namespace {

// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The weight of the point-to-point term beside the point-to-plane one.
constexpr double kPointWeight = 0.05;

Eigen::Matrix3d skew(const Vec3& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

using Tree = nanoflann::KDTreeEigenMatrixAdaptor<Points, 3, nanoflann::metric_L2_Simple, false>;

// Least-squares rotation and translation taking points p onto q (Kabsch).
RigidMotion kabsch(const std::vector<Vec3>& p, const std::vector<Vec3>& q) {
  Vec3 cp = Vec3::Zero(), cq = Vec3::Zero();
  for (size_t i = 0; i < p.size(); ++i) cp += p[i], cq += q[i];
  cp /= static_cast<double>(p.size());
  cq /= static_cast<double>(q.size());
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < p.size(); ++i) h += (p[i] - cp) * (q[i] - cq).transpose();
  RigidMotion m;
  m.rotation = kabsch_rotation(h);
  m.translation = cq - m.rotation * cp;
  return m;
}

}  // namespace

struct MeshDistance::Impl {
  Points x;
  std::vector<Triangle> triangles;
  std::vector<std::vector<int>> around;  // triangles at each vertex
  std::unique_ptr<Tree> tree;
};

MeshDistance::MeshDistance(const Points& x, const std::vector<Triangle>& triangles)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.x = x;
  m.triangles = triangles;
  m.around.resize(static_cast<size_t>(x.cols()));
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int c : triangles[t]) m.around[static_cast<size_t>(c)].push_back(static_cast<int>(t));
  m.tree = std::make_unique<Tree>(3, std::cref(m.x), 10);
  m.tree->index->buildIndex();
}

MeshDistance::~MeshDistance() = default;

double MeshDistance::distance(const Vec3& p, Vec3* closest, Vec3* normal) const {
  const Impl& m = *impl_;
  constexpr size_t k = 6;  // the triangles around the 6 nearest vertices hold the closest point
  Eigen::Index idx[k];
  double d2[k];
  const size_t found = m.tree->index->knnSearch(p.data(), std::min<size_t>(k, m.x.cols()), idx, d2);
  double best = std::numeric_limits<double>::infinity();
  Vec3 best_q = p;
  int best_t = -1;
  for (size_t i = 0; i < found; ++i)
    for (int t : m.around[static_cast<size_t>(idx[i])]) {
      const Triangle& tri = m.triangles[static_cast<size_t>(t)];
      const Vec3 q = closest_on_triangle(p, m.x.col(tri[0]), m.x.col(tri[1]), m.x.col(tri[2]));
      const double d = (q - p).squaredNorm();
      if (d < best) best = d, best_q = q, best_t = t;
    }
  if (closest) *closest = best_q;
  if (normal && best_t >= 0) {
    const Triangle& tri = m.triangles[static_cast<size_t>(best_t)];
    const Vec3 n = (m.x.col(tri[1]) - m.x.col(tri[0])).cross(m.x.col(tri[2]) - m.x.col(tri[0]));
    *normal = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
  }
  return std::sqrt(best);
}

namespace {

// From a start, a few point-to-point (Kabsch) steps bring the form near the target.
void point_to_point(const Points& form, const MeshDistance& to_target, RigidMotion& m) {
  const Eigen::Index n = form.cols();
  std::vector<Vec3> p(static_cast<size_t>(n)), q(static_cast<size_t>(n));
  for (int it = 0; it < 5; ++it) {
    for (Eigen::Index i = 0; i < n; ++i) {
      p[static_cast<size_t>(i)] = form.col(i);
      to_target.distance(m.apply(form.col(i)), &q[static_cast<size_t>(i)]);
    }
    m = kabsch(p, q);
  }
}

// Point-to-plane steps finish the alignment. Linearised: minimise sum ((w x y + t + y - q) . n)^2
// over the small turn w and shift t, with y the moved form point, q its closest target point and
// n the normal there.
void point_to_plane(const Points& form, const MeshDistance& to_target, int iterations,
                    RigidMotion& m) {
  const Eigen::Index n = form.cols();
  double previous = std::numeric_limits<double>::infinity();
  for (int it = 0; it < iterations; ++it) {
    Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    double sum = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vec3 y = m.apply(form.col(i));
      Vec3 qi, ni;
      to_target.distance(y, &qi, &ni);
      Eigen::Matrix<double, 6, 1> row;
      row.head<3>() = y.cross(ni);
      row.tail<3>() = ni;
      const double r = (y - qi).dot(ni);
      a += row * row.transpose();
      b -= row * r;
      sum += r * r;
      // A weak point-to-point term: sliding along the surface is free for the plane term alone
      // (a flat form on a cylinder would drift off along its axis).
      Eigen::Matrix<double, 3, 6> j;
      j.leftCols<3>() = -skew(y);
      j.rightCols<3>().setIdentity();
      a += kPointWeight * j.transpose() * j;
      b -= kPointWeight * j.transpose() * (y - qi);
      sum += kPointWeight * (y - qi).squaredNorm();
    }
    if (it > 0 && previous - sum <= 1e-12 * previous) break;  // no longer improving
    previous = sum;
    const Eigen::Matrix<double, 6, 1> step = a.ldlt().solve(b);
    if (!step.allFinite()) break;
    const Vec3 w = step.head<3>();
    const Eigen::Matrix3d small_turn =
        w.norm() > 0.0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                       : Eigen::Matrix3d::Identity();
    m.rotation = small_turn * m.rotation;
    m.translation = small_turn * m.translation + step.tail<3>();
  }
}

// The error of the form moved by m: both directions, each weighing half, since the vertex
// densities of form and target differ.
ShapeError error_after(const Points& form, const std::vector<Triangle>& form_triangles,
                       const TargetSurface& target, const MeshDistance& to_target,
                       const RigidMotion& m) {
  const Eigen::Index n = form.cols();
  Points moved(3, n);
  for (Eigen::Index i = 0; i < n; ++i) moved.col(i) = m.apply(form.col(i));
  const MeshDistance to_form(moved, form_triangles);
  ShapeError e;
  e.motion = m;
  double sum_f = 0.0, sum_t = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double d = to_target.distance(moved.col(i));
    e.form_distance.push_back(d);
    sum_f += d * d;
    e.max = std::max(e.max, d);
  }
  for (Eigen::Index i = 0; i < target.x.cols(); ++i) {
    const double d = to_form.distance(target.x.col(i));
    sum_t += d * d;
    e.max = std::max(e.max, d);
  }
  e.rms = std::sqrt(0.5 * sum_f / static_cast<double>(n) +
                    0.5 * sum_t / static_cast<double>(target.x.cols()));
  return e;
}

}  // namespace

ShapeError compare_shapes(const Points& form, const std::vector<Triangle>& form_triangles,
                          const TargetSurface& target, int iterations) {
  const MeshDistance to_target(target.x, target.triangles);
  const Vec3 form_centre = form.rowwise().mean();
  const Vec3 target_centre = target.x.rowwise().mean();
  ShapeError best;
  best.rms = std::numeric_limits<double>::infinity();
  // Eight starts: four turns about z, each also turned over (about x).
  for (int start = 0; start < 8; ++start) {
    const double turn = (start % 4) * 0.5 * std::numbers::pi;
    RigidMotion m;
    m.rotation = Eigen::AngleAxisd(turn, Vec3::UnitZ()).toRotationMatrix();
    if (start >= 4) m.rotation = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()) * m.rotation;
    m.translation = target_centre - m.rotation * form_centre;
    point_to_point(form, to_target, m);
    point_to_plane(form, to_target, iterations, m);
    ShapeError e = error_after(form, form_triangles, target, to_target, m);
    if (e.rms < best.rms) best = std::move(e);
  }
  return best;
}

}  // namespace membra
