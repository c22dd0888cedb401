#pragma once
// The windows on the paper behind the global form (shape.hpp) and its curvature
// (global_curvature.hpp): each particle's neighbours within a radius in the flat sheet, found
// through a bucket grid whose cells are as wide as the radius.
#include <unordered_map>
#include <vector>

#include "membra/core/vec.hpp"

namespace membra {

// The radius of the windows: 1/16 of the paper's larger side (a window 1/8 of the sheet across),
// and at least 1.75 of the larger grid spacing, so that every window holds a particle's eight
// neighbours (the diagonal ones too, on cells that are not square) and nothing depends on how a
// spacing equal to the radius rounds. 0 when there are no particles or `paper` does not match.
double window_radius(const Points& x, const Points& paper);

// A sheet of so many particles that its windows are summed by grid rows (paper_rows.hpp), every
// particle counted, rather than visited one by one. (Until 2026-12-05 such windows took every
// stride-th particle instead, which aliased with the grid and moved the global form and its
// curvature: docs/measures.md.)
bool big_sheet(Eigen::Index particles);

class PaperWindows {
 public:
  PaperWindows(const Points& paper, double radius);
  // The particles within the radius of p on the paper (p among them) into `out`, cleared first.
  void collect(Eigen::Index p, std::vector<Eigen::Index>& out) const;

 private:
  std::pair<long, long> cell(Eigen::Index p) const;

  const Points& paper_;
  double radius_;
  Vec3 lo_;
  std::unordered_map<long, std::vector<Eigen::Index>> buckets_;
};

}  // namespace membra
