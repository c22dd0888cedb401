#include "membra/measure/paper_rows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace membra {

namespace {

using Members = std::vector<std::pair<double, Eigen::Index>>;  // (x, particle)

// The half-width of the window's chord at height y: the row test of every window.
double chord(const Vec2& centre, double radius, double y) {
  const double dy = y - centre.y();
  return std::sqrt(std::max(0.0, radius * radius - dy * dy));
}

}  // namespace

PaperRows::PaperRows(const Points& paper, const Eigen::MatrixXd& values) : size_(values.rows()) {
  const Eigen::Index n = paper.cols();
  std::map<double, Members> by_y;
  for (Eigen::Index p = 0; p < n; ++p) by_y[paper(1, p)].push_back({paper(0, p), p});
  // A grid of n particles has about sqrt(n) rows; a mesh's vertices far more distinct y (a mesh
  // graded along straight outlines shares some, so a count near n is not the test): those go
  // into bands of about sqrt(n) particles.
  const double rows_of_a_grid = std::sqrt(static_cast<double>(n));
  banded_ = n > 0 && static_cast<double>(by_y.size()) > 4.0 * rows_of_a_grid;
  if (banded_) {
    const double y0 = by_y.begin()->first, y1 = by_y.rbegin()->first;
    band_ = std::max((y1 - y0) / std::ceil(std::sqrt(static_cast<double>(n))), 1e-300);
    std::map<double, Members> bands;  // keyed by the band's index
    for (auto& [y, members] : by_y)
      for (const auto& m : members) bands[std::floor((y - y0) / band_)].push_back(m);
    by_y = std::move(bands);
  }
  for (auto& [key, members] : by_y) {
    std::sort(members.begin(), members.end());
    const auto count = static_cast<Eigen::Index>(members.size());
    Row r;
    r.prefix = Eigen::MatrixXd::Zero(size_, count + 1);
    if (banded_) r.value.resize(size_, count);
    r.y_lo = r.y_hi = paper(1, members.front().second);
    for (Eigen::Index k = 0; k < count; ++k) {
      const Eigen::Index p = members[static_cast<size_t>(k)].second;
      r.x.push_back(paper(0, p));
      r.prefix.col(k + 1) = r.prefix.col(k) + values.col(p);
      r.y_lo = std::min(r.y_lo, paper(1, p));
      r.y_hi = std::max(r.y_hi, paper(1, p));
      if (!banded_) continue;
      r.y.push_back(paper(1, p));
      r.value.col(k) = values.col(p);
    }
    y_.push_back(r.y_lo);
    rows_.push_back(std::move(r));
  }
}

Eigen::VectorXd PaperRows::sum_within(const Vec2& centre, double radius) const {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(size_);
  if (banded_) {
    // Bands start at y_; one starting a band's height below the window may reach into it.
    const auto first = std::lower_bound(y_.begin(), y_.end(), centre.y() - radius - band_);
    for (auto y = first; y != y_.end() && *y <= centre.y() + radius; ++y)
      add_banded(rows_[static_cast<size_t>(y - y_.begin())], centre, radius, sum);
    return sum;
  }
  const auto first = std::lower_bound(y_.begin(), y_.end(), centre.y() - radius);
  for (auto y = first; y != y_.end() && *y <= centre.y() + radius; ++y) {
    const double w = chord(centre, radius, *y);
    const Row& r = rows_[static_cast<size_t>(y - y_.begin())];
    const auto lo = std::lower_bound(r.x.begin(), r.x.end(), centre.x() - w) - r.x.begin();
    const auto hi = std::upper_bound(r.x.begin(), r.x.end(), centre.x() + w) - r.x.begin();
    sum += r.prefix.col(hi) - r.prefix.col(lo);
  }
  return sum;
}

// A band inside the window's height: particles within the narrowest chord over the band's y are
// inside (prefix sums), those between it and the widest are tested one by one, each by its own
// row's test. A band reaching past the window's top or bottom tests every candidate.
void PaperRows::add_banded(const Row& r, const Vec2& centre, double radius,
                           Eigen::VectorXd& sum) const {
  if (r.y_hi < centre.y() - radius || r.y_lo > centre.y() + radius) return;
  const bool inside = r.y_lo >= centre.y() - radius && r.y_hi <= centre.y() + radius;
  const double w_min =
      inside ? std::min(chord(centre, radius, r.y_lo), chord(centre, radius, r.y_hi)) : -1.0;
  const double w_max = chord(centre, radius, std::clamp(centre.y(), r.y_lo, r.y_hi));
  const auto at = [&](double x) {
    return std::lower_bound(r.x.begin(), r.x.end(), x) - r.x.begin();
  };
  const auto after = [&](double x) {
    return std::upper_bound(r.x.begin(), r.x.end(), x) - r.x.begin();
  };
  const Eigen::Index a = at(centre.x() - w_max), d = after(centre.x() + w_max);
  Eigen::Index b = a, c = a;  // [b, c): surely inside
  if (w_min >= 0.0) {
    b = at(centre.x() - w_min);
    c = after(centre.x() + w_min);
    sum += r.prefix.col(c) - r.prefix.col(b);
  }
  const auto test = [&](Eigen::Index k) {
    const auto kk = static_cast<size_t>(k);
    if (std::abs(r.y[kk] - centre.y()) > radius) return;
    const double w = chord(centre, radius, r.y[kk]);
    if (r.x[kk] >= centre.x() - w && r.x[kk] <= centre.x() + w) sum += r.value.col(k);
  };
  for (Eigen::Index k = a; k < b; ++k) test(k);
  for (Eigen::Index k = c; k < d; ++k) test(k);  // c >= a: w_min <= w_max
}

}  // namespace membra
