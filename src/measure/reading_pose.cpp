#include "membra/measure/reading_pose.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace membra {
namespace {

// The unit normal of the points' least-squares plane, and its largest principal axis.
void principal_axes(const Points& x, Vec3& normal, Vec3& longest) {
  const Vec3 mean = x.rowwise().mean();
  const Eigen::Matrix3Xd d = x.colwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(d * d.transpose());
  normal = eig.eigenvectors().col(0);
  longest = eig.eigenvectors().col(2);
}

// The unit vector along v's part perpendicular to n, or `fallback` when v is (nearly) along n.
Vec3 in_plane(const Vec3& v, const Vec3& n, const Vec3& fallback) {
  const Vec3 p = v - v.dot(n) * n;
  return p.norm() > 1e-6 ? Vec3(p.normalized()) : fallback;
}

}  // namespace

RigidMotion reading_pose(const Points& x, const QuadricFit& q) {
  RigidMotion pose;
  if (x.cols() < 3) return pose;
  Vec3 ez, ex;
  const bool described = q.valid && q.classification != "flat" && q.classification != "folded";
  if (described) {
    ez = q.normal;
    // Of the principal directions, the one nearer the paper's x axis, pointing along it; on a
    // nearly round cap (k1 and k2 within 10 %) they are arbitrary, and the paper's x is used.
    const bool round = std::abs(q.k1 - q.k2) < 0.1 * std::max(std::abs(q.k1), std::abs(q.k2));
    ex = std::abs(q.d1.dot(q.paper_x)) >= std::abs(q.d2.dot(q.paper_x)) ? q.d1 : q.d2;
    if (round) ex = q.paper_x;
    if (ex.dot(q.paper_x) < 0.0) ex = -ex;
    ex = in_plane(ex, ez, ex);
  } else {
    Vec3 longest;
    principal_axes(x, ez, longest);
    if (q.valid && ez.dot(q.normal) < 0.0) ez = -ez;
    ex = in_plane(q.valid ? q.paper_x : longest, ez, in_plane(longest, ez, Vec3::UnitX()));
  }
  const Vec3 ey = ez.cross(ex);
  pose.rotation.row(0) = ex.transpose();
  pose.rotation.row(1) = ey.transpose();
  pose.rotation.row(2) = ez.transpose();
  const Eigen::Matrix3Xd turned = pose.rotation * x;
  const Vec3 lo = turned.rowwise().minCoeff(), hi = turned.rowwise().maxCoeff();
  pose.translation = -Vec3(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z());
  return pose;
}

}  // namespace membra
