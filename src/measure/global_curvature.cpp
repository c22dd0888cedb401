#include "membra/measure/global_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "membra/measure/paper_rows.hpp"
#include "membra/measure/paper_windows.hpp"
#include "membra/measure/shape.hpp"

namespace membra {

namespace {

// The density averaged over every interior vertex within `radius` (paper_rows.hpp). A window's
// defects sum to what its rim turns (Gauss-Bonnet), so wrinkles cancel only when none is left
// out: thinning the windows of big sheets, as was done until 2026-12-05, aliased with the grid
// and misread a wrinkled bowl at 301^2.
std::vector<double> window_densities(const Points& paper, double radius,
                                     const GaussianCurvature& k) {
  Eigen::MatrixXd values = Eigen::MatrixXd::Zero(2, paper.cols());
  for (Eigen::Index p = 0; p < paper.cols(); ++p)
    if (k.interior[static_cast<size_t>(p)])
      values.col(p) << k.angle_defect[static_cast<size_t>(p)], k.area[static_cast<size_t>(p)];
  const PaperRows rows(paper, values);
  std::vector<double> out(k.density.size(), 0.0);
  for (Eigen::Index p = 0; p < paper.cols(); ++p) {
    if (!k.interior[static_cast<size_t>(p)]) continue;
    const Eigen::VectorXd sum = rows.sum_within(paper.col(p).head<2>(), radius);
    out[static_cast<size_t>(p)] = sum[1] > 0.0 ? sum[0] / sum[1] : 0.0;
  }
  return out;
}

}  // namespace

void average_density_over_windows(const Points& paper, double radius, GaussianCurvature& k) {
  if (k.interior.size() != static_cast<size_t>(paper.cols()) || !(radius > 0.0))
    throw std::invalid_argument(
        "average_density_over_windows: one paper position per vertex "
        "and a radius > 0");
  if (big_sheet(paper.cols())) {
    set_smoothed_density(k, window_densities(paper, radius, k));
    return;
  }
  const PaperWindows windows(paper, radius);
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
