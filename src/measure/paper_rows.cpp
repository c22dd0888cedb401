#include "membra/measure/paper_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace membra {

PaperRows::PaperRows(const Points& paper, const Eigen::MatrixXd& values) : size_(values.rows()) {
  std::map<double, std::vector<std::pair<double, Eigen::Index>>> by_y;
  for (Eigen::Index p = 0; p < paper.cols(); ++p) by_y[paper(1, p)].push_back({paper(0, p), p});
  for (auto& [y, members] : by_y) {
    std::sort(members.begin(), members.end());
    Row r{{}, Eigen::MatrixXd::Zero(size_, static_cast<Eigen::Index>(members.size()) + 1)};
    for (size_t k = 0; k < members.size(); ++k) {
      r.x.push_back(members[k].first);
      const auto c = static_cast<Eigen::Index>(k);
      r.prefix.col(c + 1) = r.prefix.col(c) + values.col(members[k].second);
    }
    y_.push_back(y);
    rows_.push_back(std::move(r));
  }
}

Eigen::VectorXd PaperRows::sum_within(const Vec2& centre, double radius) const {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(size_);
  const auto first = std::lower_bound(y_.begin(), y_.end(), centre.y() - radius);
  for (auto y = first; y != y_.end() && *y <= centre.y() + radius; ++y) {
    const double dy = *y - centre.y(), w = std::sqrt(std::max(0.0, radius * radius - dy * dy));
    const Row& r = rows_[static_cast<size_t>(y - y_.begin())];
    const auto lo = std::lower_bound(r.x.begin(), r.x.end(), centre.x() - w) - r.x.begin();
    const auto hi = std::upper_bound(r.x.begin(), r.x.end(), centre.x() + w) - r.x.begin();
    sum += r.prefix.col(hi) - r.prefix.col(lo);
  }
  return sum;
}

}  // namespace membra
