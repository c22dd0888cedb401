#include "membra/measure/shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <vector>

#include <Eigen/Eigenvalues>

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

Neighbourhoods paper_neighbourhoods(const Points& x, const Points& paper, double radius,
                                    double size) {
  const auto n = x.cols();
  // A window holds about n pi / 256 particles (radius size/16); a few hundred describe its mean
  // and plane as well as all of them, so big sheets take every stride-th one (index order
  // within a bucket is row order on the grid: an even thinning).
  const double expected =
      static_cast<double>(n) * radius * radius * std::numbers::pi / (size * size);
  const size_t stride = std::max<size_t>(1, static_cast<size_t>(expected / 400.0));
  const Vec3 lo = paper.rowwise().minCoeff();
  auto cell = [&](const Vec3& p) {
    return std::pair<long, long>{std::lround(std::floor((p.x() - lo.x()) / radius)),
                                 std::lround(std::floor((p.y() - lo.y()) / radius))};
  };
  auto key = [](long i, long j) { return (i << 32) ^ (j & 0xffffffffL); };
  std::unordered_map<long, std::vector<Eigen::Index>> buckets;
  for (Eigen::Index p = 0; p < n; ++p) {
    const auto [i, j] = cell(paper.col(p));
    buckets[key(i, j)].push_back(p);
  }
  Neighbourhoods out{Points(3, n), Eigen::VectorXd::Zero(n)};
  const double r2 = radius * radius;
  std::vector<Eigen::Index> near;
  for (Eigen::Index p = 0; p < n; ++p) {
    const auto [i, j] = cell(paper.col(p));
    near.clear();
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di) {
        const auto it = buckets.find(key(i + di, j + dj));
        if (it == buckets.end()) continue;
        const std::vector<Eigen::Index>& bucket = it->second;
        for (size_t k = 0; k < bucket.size(); k += stride) {
          const Eigen::Index q = bucket[k];
          if ((paper.col(q) - paper.col(p)).head<2>().squaredNorm() <= r2) near.push_back(q);
        }
      }
    if (near.empty()) near.push_back(p);
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

// The grid spacing along one paper axis: the median gap between distinct coordinates (a sheet is
// a grid on the paper; holes and masks remove particles, not columns, and the median ignores a
// stray gap). Coordinates closer than 1e-9 of the extent are one column.
double axis_spacing(const Eigen::RowVectorXd& coordinate) {
  std::vector<double> c(coordinate.data(), coordinate.data() + coordinate.size());
  std::sort(c.begin(), c.end());
  const double same = 1e-9 * std::max(c.back() - c.front(), 1e-300);
  std::vector<double> gaps;
  for (size_t i = 1; i < c.size(); ++i)
    if (c[i] - c[i - 1] > same) gaps.push_back(c[i] - c[i - 1]);
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  return gaps[gaps.size() / 2];
}

}  // namespace

// The window radius of the global/fold split: 1/16 of the paper's larger side, and at least 1.75
// of the larger grid spacing, so that every window holds a particle's eight neighbours (the
// diagonal ones too, on cells that are not square) and nothing depends on how a spacing equal to
// the radius rounds (0: no particles).
double window_radius(const Points& x, const Points& paper) {
  if (x.cols() == 0 || paper.cols() != x.cols()) return 0.0;
  const Vec3 extent = paper.rowwise().maxCoeff() - paper.rowwise().minCoeff();
  const double spacing = std::max(axis_spacing(paper.row(0)), axis_spacing(paper.row(1)));
  return std::max(std::max(extent.x(), extent.y()) / 16.0, 1.75 * spacing);
}

Points global_form(const Points& x, const Points& paper) {
  const double radius = window_radius(x, paper);
  if (!(radius > 0.0)) return Points();
  return paper_neighbourhoods(x, paper, radius, 16.0 * radius).mean;
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
  const Neighbourhoods near = paper_neighbourhoods(x, paper, radius, 16.0 * radius);
  s.global_height = height_over_best_plane(near.mean);
  s.fold_rms = std::sqrt(near.fold.squaredNorm() / static_cast<double>(x.cols()));
  s.fold_max = near.fold.maxCoeff();
  s.quadric = fit_quadric(x, paper);
  return s;
}

}  // namespace membra
