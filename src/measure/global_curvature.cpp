#include "membra/measure/global_curvature.hpp"

#include <stdexcept>

#include "membra/measure/paper_windows.hpp"
#include "membra/measure/shape.hpp"

namespace membra {

void average_density_over_windows(const Points& paper, double radius, GaussianCurvature& k) {
  if (k.interior.size() != static_cast<size_t>(paper.cols()) || !(radius > 0.0))
    throw std::invalid_argument(
        "average_density_over_windows: one paper position per vertex "
        "and a radius > 0");
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
