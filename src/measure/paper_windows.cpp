#include "membra/measure/paper_windows.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace membra {
namespace {

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

long bucket_key(long i, long j) {
  return (i << 32) ^ (j & 0xffffffffL);
}

}  // namespace

double window_radius(const Points& x, const Points& paper) {
  if (x.cols() == 0 || paper.cols() != x.cols()) return 0.0;
  const Vec3 extent = paper.rowwise().maxCoeff() - paper.rowwise().minCoeff();
  const double spacing = std::max(axis_spacing(paper.row(0)), axis_spacing(paper.row(1)));
  return std::max(std::max(extent.x(), extent.y()) / 16.0, 1.75 * spacing);
}

bool big_sheet(Eigen::Index particles) {
  // A window of radius 1/16 of the sheet holds about N pi / 256 particles; from 800 on (about
  // 256^2), summing rows' prefix sums costs less than visiting each.
  const double expected = static_cast<double>(particles) * std::numbers::pi / 256.0;
  return expected / 400.0 >= 2.0;
}

PaperWindows::PaperWindows(const Points& paper, double radius)
    : paper_(paper), radius_(radius), lo_(paper.rowwise().minCoeff()) {
  for (Eigen::Index p = 0; p < paper.cols(); ++p) {
    const auto [i, j] = cell(p);
    buckets_[bucket_key(i, j)].push_back(p);
  }
}

std::pair<long, long> PaperWindows::cell(Eigen::Index p) const {
  return {std::lround(std::floor((paper_(0, p) - lo_.x()) / radius_)),
          std::lround(std::floor((paper_(1, p) - lo_.y()) / radius_))};
}

void PaperWindows::collect(Eigen::Index p, std::vector<Eigen::Index>& out) const {
  out.clear();
  const auto [i, j] = cell(p);
  const double r2 = radius_ * radius_;
  for (long dj = -1; dj <= 1; ++dj)
    for (long di = -1; di <= 1; ++di) {
      const auto it = buckets_.find(bucket_key(i + di, j + dj));
      if (it == buckets_.end()) continue;
      const std::vector<Eigen::Index>& bucket = it->second;
      for (const Eigen::Index q : bucket) {
        if ((paper_.col(q) - paper_.col(p)).head<2>().squaredNorm() <= r2) out.push_back(q);
      }
    }
  if (out.empty()) out.push_back(p);
}

}  // namespace membra
