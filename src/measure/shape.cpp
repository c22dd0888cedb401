#include "membra/measure/shape.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

#include "membra/measure/paper_rows.hpp"
#include "membra/measure/paper_windows.hpp"

namespace membra {

double height_over_best_plane(const Points& x, Vec3* normal) {
  if (x.cols() == 0) return 0.0;
  const Vec3 centroid = x.rowwise().mean();
  const Points centred = x.colwise() - centroid;
  const Eigen::Matrix3d cov = centred * centred.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vec3 n = eig.eigenvectors().col(0);  // eigenvalues ascend: column 0 is the plane normal
  if (n.z() < 0) n = -n;
  if (normal) *normal = n;
  const Eigen::RowVectorXd h = n.transpose() * centred;
  return h.maxCoeff() - h.minCoeff();
}

namespace {

// Each particle's neighbourhood: the particles within `radius` of it on the paper (found
// through a bucket grid of cell `radius`). Its linear fit at the particle is the global form
// there (`mean`: the neighbourhood's mean away from the edges); the
// distance of the particle from the neighbourhood's least-squares plane is its fold.
struct Neighbourhoods {
  Points mean;
  Eigen::VectorXd fold;
};

// The value at p of the least-squares linear fit of the positions over the neighbourhood's paper
// coordinates. For a symmetric neighbourhood that is its mean; at the sheet's edge, where the
// neighbourhood is one-sided and its mean lies inside the sheet, the fit is not pulled inwards
// (the mean was: on coarse grids the global form's rim then folded and its total curvature came
// out several times the sheet's own).
Vec3 linear_fit_at(const Points& x, const Points& paper, Eigen::Index p,
                   const std::vector<Eigen::Index>& near, const Vec3& mean) {
  Vec2 centre = Vec2::Zero();
  for (Eigen::Index q : near) centre += paper.col(q).head<2>();
  centre /= static_cast<double>(near.size());
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 3, 2> b = Eigen::Matrix<double, 3, 2>::Zero();
  for (Eigen::Index q : near) {
    const Vec2 u = paper.col(q).head<2>() - centre;
    a += u * u.transpose();
    b += (x.col(q) - mean) * u.transpose();
  }
  // Collinear or single points: no slope across the line, the mean is the best there is.
  if (!(a.determinant() > 1e-9 * a.trace() * a.trace())) return mean;
  return mean + b * a.inverse() * (paper.col(p).head<2>() - centre);
}

// paper_neighbourhoods from every particle of each window, for big sheets (the moments of a
// window, summed by grid rows: paper_rows.hpp): the same linear fit and fold, from sums. Thinned
// means had shifted the global form's rim: a wrinkled bowl's total curvature read 1.20 rad at 161^2
// and 321^2 but 1.43 at 513^2, windows thinned 8-fold.
Neighbourhoods neighbourhoods_by_rows(const Points& x, const Points& paper, double radius) {
  const auto n = x.cols();
  // Moments about the centroids, which keeps the sums' cancellation small.
  const Vec2 c0 = paper.topRows<2>().rowwise().mean();
  const Vec3 x0 = x.rowwise().mean();
  Eigen::MatrixXd m(21, n);
  for (Eigen::Index p = 0; p < n; ++p) {
    const Vec2 u = paper.col(p).head<2>() - c0;
    const Vec3 d = x.col(p) - x0;
    m.col(p) << 1.0, u, u.x() * u.x(), u.x() * u.y(), u.y() * u.y(), d, d.x() * u, d.y() * u,
        d.z() * u, d.x() * d.x(), d.x() * d.y(), d.x() * d.z(), d.y() * d.y(), d.y() * d.z(),
        d.z() * d.z();
  }
  const PaperRows rows(paper, m);
  Neighbourhoods out{Points(3, n), Eigen::VectorXd::Zero(n)};
  for (Eigen::Index p = 0; p < n; ++p) {
    const Eigen::VectorXd s = rows.sum_within(paper.col(p).head<2>(), radius);
    const double count = s[0];
    const Vec2 centre = s.segment<2>(1) / count;
    Eigen::Matrix2d a;
    a << s[3], s[4], s[4], s[5];
    a -= count * centre * centre.transpose();
    const Vec3 mean = s.segment<3>(6) / count;
    Eigen::Matrix<double, 3, 2> b;
    b << s[9], s[10], s[11], s[12], s[13], s[14];
    b -= count * mean * centre.transpose();
    Vec3 fit = mean;  // collinear or single points: no slope across the line
    if (a.determinant() > 1e-9 * a.trace() * a.trace())
      fit += b * a.inverse() * (paper.col(p).head<2>() - c0 - centre);
    out.mean.col(p) = fit + x0;
    if (count < 3.0) continue;
    Eigen::Matrix3d cov;
    cov << s[15], s[16], s[17], s[16], s[18], s[19], s[17], s[19], s[20];
    cov -= count * mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    out.fold[p] = std::abs(eig.eigenvectors().col(0).dot(x.col(p) - x0 - mean));
  }
  return out;
}

Neighbourhoods paper_neighbourhoods(const Points& x, const Points& paper, double radius) {
  const auto n = x.cols();
  if (big_sheet(paper.cols())) return neighbourhoods_by_rows(x, paper, radius);
  const PaperWindows windows(paper, radius);
  Neighbourhoods out{Points(3, n), Eigen::VectorXd::Zero(n)};
  std::vector<Eigen::Index> near;
  for (Eigen::Index p = 0; p < n; ++p) {
    windows.collect(p, near);
    Vec3 mean = Vec3::Zero();
    for (Eigen::Index q : near) mean += x.col(q);
    mean /= static_cast<double>(near.size());
    out.mean.col(p) = linear_fit_at(x, paper, p, near, mean);
    if (near.size() < 3) continue;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (Eigen::Index q : near) cov += (x.col(q) - mean) * (x.col(q) - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    out.fold[p] = std::abs(eig.eigenvectors().col(0).dot(x.col(p) - mean));
  }
  return out;
}

}  // namespace

Points global_form(const Points& x, const Points& paper) {
  const double radius = window_radius(x, paper);
  if (!(radius > 0.0)) return Points();
  return paper_neighbourhoods(x, paper, radius).mean;
}

ShapeSummary summarize_shape(const Points& x, const Points& paper) {
  ShapeSummary s;
  if (x.cols() == 0) return s;
  s.bbox_min = x.rowwise().minCoeff();
  s.bbox_max = x.rowwise().maxCoeff();
  s.z_range = s.bbox_max.z() - s.bbox_min.z();
  s.height = height_over_best_plane(x, &s.normal);
  const double radius = window_radius(x, paper);
  if (!(radius > 0.0)) return s;
  const Neighbourhoods near = paper_neighbourhoods(x, paper, radius);
  s.global_height = height_over_best_plane(near.mean);
  s.fold_rms = std::sqrt(near.fold.squaredNorm() / static_cast<double>(x.cols()));
  s.fold_max = near.fold.maxCoeff();
  s.quadric = fit_quadric(x, paper);
  return s;
}

}  // namespace membra
