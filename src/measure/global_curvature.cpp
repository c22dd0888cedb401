#include "membra/measure/global_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "membra/measure/paper_windows.hpp"
#include "membra/measure/shape.hpp"

namespace membra {

namespace {

// Sums of the angle defects and areas of interior vertices within `radius` on the paper, every
// vertex counted: by rows of equal paper y, each with prefix sums along x, so a window costs a
// binary search per row it crosses. (A window's defects sum to what its rim turns, Gauss-Bonnet,
// so wrinkles cancel only when none is left out: thinning a window, as PaperWindows does on big
// sheets for means, aliased with the grid and misread a wrinkled bowl at 301^2.) The paper is a
// grid: each row's particles share one y exactly.
std::vector<double> window_densities(const Points& paper, double radius,
                                     const GaussianCurvature& k) {
  struct Row {
    std::vector<double> x, defect, area;  // x sorted; defect and area: prefix sums (size + 1)
  };
  std::map<double, std::vector<std::pair<double, size_t>>> by_y;
  for (Eigen::Index p = 0; p < paper.cols(); ++p)
    if (k.interior[static_cast<size_t>(p)])
      by_y[paper(1, p)].push_back({paper(0, p), static_cast<size_t>(p)});
  std::vector<double> ys;
  std::vector<Row> rows;
  for (auto& [y, members] : by_y) {
    std::sort(members.begin(), members.end());
    Row r{{}, {0.0}, {0.0}};
    for (const auto& [x, p] : members) {
      r.x.push_back(x);
      r.defect.push_back(r.defect.back() + k.angle_defect[p]);
      r.area.push_back(r.area.back() + k.area[p]);
    }
    ys.push_back(y);
    rows.push_back(std::move(r));
  }
  std::vector<double> out(k.density.size(), 0.0);
  for (Eigen::Index p = 0; p < paper.cols(); ++p) {
    if (!k.interior[static_cast<size_t>(p)]) continue;
    const double px = paper(0, p), py = paper(1, p);
    double defect = 0.0, area = 0.0;
    const auto first = std::lower_bound(ys.begin(), ys.end(), py - radius);
    for (auto y = first; y != ys.end() && *y <= py + radius; ++y) {
      const double dy = *y - py, w = std::sqrt(std::max(0.0, radius * radius - dy * dy));
      const Row& r = rows[static_cast<size_t>(y - ys.begin())];
      const auto lo = std::lower_bound(r.x.begin(), r.x.end(), px - w) - r.x.begin();
      const auto hi = std::upper_bound(r.x.begin(), r.x.end(), px + w) - r.x.begin();
      defect += r.defect[static_cast<size_t>(hi)] - r.defect[static_cast<size_t>(lo)];
      area += r.area[static_cast<size_t>(hi)] - r.area[static_cast<size_t>(lo)];
    }
    out[static_cast<size_t>(p)] = area > 0.0 ? defect / area : 0.0;
  }
  return out;
}

}  // namespace

void average_density_over_windows(const Points& paper, double radius, GaussianCurvature& k) {
  if (k.interior.size() != static_cast<size_t>(paper.cols()) || !(radius > 0.0))
    throw std::invalid_argument(
        "average_density_over_windows: one paper position per vertex "
        "and a radius > 0");
  const PaperWindows windows(paper, radius);
  if (windows.thinned()) {  // big sheets: every vertex summed by rows (smaller ones as before)
    set_smoothed_density(k, window_densities(paper, radius, k));
    return;
  }
  std::vector<double> out(k.density.size(), 0.0);
  std::vector<Eigen::Index> near;
  for (Eigen::Index p = 0; p < paper.cols(); ++p) {
    const auto sp = static_cast<size_t>(p);
    if (!k.interior[sp]) continue;
    windows.collect(p, near);
    double defect = 0.0, area = 0.0;
    for (Eigen::Index q : near) {
      const auto sq = static_cast<size_t>(q);
      if (!k.interior[sq]) continue;
      defect += k.angle_defect[sq];
      area += k.area[sq];
    }
    out[sp] = area > 0.0 ? defect / area : 0.0;
  }
  set_smoothed_density(k, std::move(out));
}

GaussianCurvature global_curvature(const Points& x, const Points& paper,
                                   const std::vector<Triangle>& tris) {
  const Points global = global_form(x, paper);
  if (global.cols() != x.cols() || x.cols() == 0) return {};
  GaussianCurvature k = gaussian_curvature(global, tris);
  // Twice the form's window: waves as long as the form's window average out of the density (at
  // the form's own radius the ellipse at 41^2 read +6.6 / -3.3 rad, at twice it +5.4 / -1.5, the
  // bowl its picture shows; docs/measures.md).
  average_density_over_windows(paper, 2.0 * window_radius(x, paper), k);
  return k;
}

}  // namespace membra
